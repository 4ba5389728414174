#include "ancfnet/study/study_progress.hpp"

#include <fmt/format.h>

namespace ancfnet {

StudyProgress::StudyProgress(std::size_t cases, std::size_t done, std::size_t failed,
                             std::FILE* stream)
    : cases_(cases),
      done_(done),
      failed_(failed),
      stream_(stream),
      start_(std::chrono::steady_clock::now()) {}

void StudyProgress::Record(const CaseResult& result) {
  ++done_;
  ++done_here_;
  if (!result.ok) ++failed_;
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double left =
      elapsed / static_cast<double>(done_here_) * static_cast<double>(cases_ - done_);
  const std::string outcome =
      result.ok ? std::string("ok") : fmt::format("failed: {}", result.reason);
  fmt::print(stream_, "study: {}/{} cases done ({} failed), about {:.0f} s left; case {} {}\n",
             done_, cases_, failed_, left, result.index, outcome);
  std::fflush(stream_);
}

}  // namespace ancfnet
