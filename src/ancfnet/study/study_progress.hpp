#pragma once
/// @file A study's progress on stderr: cases done and failed out of all, and the time left.

#include <chrono>
#include <cstddef>
#include <cstdio>

#include "ancfnet/study/case_result.hpp"

namespace ancfnet {

class StudyProgress {
 public:
  /// `cases` in all, of which `done` and `failed` finished before (a resumed study).
  StudyProgress(std::size_t cases, std::size_t done, std::size_t failed, std::FILE* stream);
  /// Counts `result` and prints one line "study: D/N cases done (F failed), about T s left",
  /// the time left extrapolated from the cases finished since the start.
  void Record(const CaseResult& result);

  std::size_t done() const { return done_; }
  std::size_t failed() const { return failed_; }

 private:
  std::size_t cases_;
  std::size_t done_;
  std::size_t failed_;
  std::size_t done_here_ = 0;
  std::FILE* stream_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace ancfnet
