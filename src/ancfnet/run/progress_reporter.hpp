#pragma once
/// @file A progress line on stderr for runs longer than a second.

#include <chrono>
#include <string>

namespace ancfnet {

/// Rewrites one line on stderr ("t = 0.42 / 1 s  42 %  …") at most a few times a second, and only
/// once the run has taken more than a second. Finish() ends the line if one was written.
class ProgressReporter {
 public:
  ProgressReporter(std::string label, double end, bool enabled);
  /// Reports progress `value` out of `end` and the number of outputs written; formats nothing
  /// unless a line is due.
  void Update(double value, long outputs);
  void Finish();
  /// Seconds since construction.
  double elapsed_s() const;

 private:
  std::string label_;
  double end_;
  bool enabled_;
  bool written_ = false;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace ancfnet
