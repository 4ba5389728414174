#include "ancfnet/run/progress_reporter.hpp"

#include <cstdio>

namespace ancfnet {

ProgressReporter::ProgressReporter(std::string label, double end, bool enabled)
    : label_(std::move(label)), end_(end), enabled_(enabled),
      start_(std::chrono::steady_clock::now()), last_(start_) {}

double ProgressReporter::elapsed_s() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void ProgressReporter::Update(double value, long outputs) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (elapsed_s() < 1.0 || now - last_ < std::chrono::milliseconds(250)) return;
  last_ = now;
  written_ = true;
  std::fprintf(stderr, "\r%s %.6g / %.6g  %3.0f %%  %ld outputs  %.1f s   ", label_.c_str(), value,
               end_, 100.0 * value / end_, outputs, elapsed_s());
  std::fflush(stderr);
}

void ProgressReporter::Finish() {
  if (written_) std::fputc('\n', stderr);
  written_ = false;
}

}  // namespace ancfnet
