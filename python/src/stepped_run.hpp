#pragma once
/// @file SteppedRun: a run of a scene that stops at each output step until asked to go on, so
/// that a caller (Python) can read the state between steps of the very run `ancfnet run` makes.

#include <condition_variable>
#include <exception>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include "ancfnet/io/scene.hpp"
#include "ancfnet/io/summary_writer.hpp"
#include "ancfnet/state/state.hpp"

namespace ancfnet::python {

/// RunScene (the CLI's run: probes.csv, VTK frames, summary.json in `output_dir`) driven one
/// output step at a time. A worker thread runs it and waits in its output hook while the caller
/// holds the turn, so the steps, outputs and final state are bit for bit those of one RunScene.
class SteppedRun {
 public:
  SteppedRun(std::shared_ptr<const Scene> scene, std::filesystem::path output_dir);
  SteppedRun(const SteppedRun&) = delete;
  SteppedRun& operator=(const SteppedRun&) = delete;
  /// Abandons a run still in progress (its summary.json is not written).
  ~SteppedRun();

  /// Runs to the next output step (the first call stops at the initial state) and returns true,
  /// or returns false once the run has ended (summary() is then set). Rethrows what RunScene
  /// throws (InputError when the output directory cannot be written).
  bool Advance();

  /// The state at the last output step (the initial state before the first Advance). Its
  /// vectors keep their storage from one step to the next.
  const State& state() const { return state_; }
  /// How the run ended; empty while it is in progress or when it raised.
  const std::optional<RunSummary>& summary() const { return summary_; }
  /// True once the run has ended (Advance returned false or raised).
  bool finished() const { return finished_; }
  const std::filesystem::path& output_dir() const { return output_dir_; }

 private:
  enum class Turn { kCaller, kWorker };
  void Work();
  // Hands the turn to `next` and waits until it comes back to `self`.
  void PassTurn(std::unique_lock<std::mutex>& lock, Turn next, Turn self);

  std::shared_ptr<const Scene> scene_;
  std::filesystem::path output_dir_;
  State state_;
  std::optional<RunSummary> summary_;
  std::exception_ptr error_;
  std::mutex mutex_;
  std::condition_variable turn_changed_;
  Turn turn_ = Turn::kCaller;
  bool finished_ = false;
  bool abandon_ = false;
  std::thread worker_;
};

}  // namespace ancfnet::python
