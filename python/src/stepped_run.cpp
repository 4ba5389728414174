#include "stepped_run.hpp"

#include <utility>

#include "ancfnet/run/run_scene.hpp"

namespace ancfnet::python {
namespace {

// Thrown in the worker from the output hook to unwind an abandoned run.
struct Abandoned {};

}  // namespace

SteppedRun::SteppedRun(std::shared_ptr<const Scene> scene, std::filesystem::path output_dir)
    : scene_(std::move(scene)),
      output_dir_(std::move(output_dir)),
      state_(MakeInitialState(scene_->model)) {}

SteppedRun::~SteppedRun() {
  if (!worker_.joinable()) return;
  {
    std::unique_lock lock(mutex_);
    abandon_ = true;
    turn_ = Turn::kWorker;
  }
  turn_changed_.notify_all();
  worker_.join();
}

void SteppedRun::PassTurn(std::unique_lock<std::mutex>& lock, Turn next, Turn self) {
  turn_ = next;
  turn_changed_.notify_all();
  turn_changed_.wait(lock, [&] { return turn_ == self; });
}

bool SteppedRun::Advance() {
  std::unique_lock lock(mutex_);
  if (finished_) return false;
  if (worker_.joinable()) {
    PassTurn(lock, Turn::kWorker, Turn::kCaller);
  } else {
    turn_ = Turn::kWorker;
    worker_ = std::thread(&SteppedRun::Work, this);
    turn_changed_.wait(lock, [&] { return turn_ == Turn::kCaller; });
  }
  if (!finished_) return true;
  worker_.join();
  if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
  return false;
}

void SteppedRun::Work() {
  RunOptions options;
  options.output_dir = output_dir_;
  options.show_progress = false;
  options.on_output = [this](const State& state) {
    std::unique_lock lock(mutex_);
    state_ = state;  // same sizes: the vectors keep their storage
    PassTurn(lock, Turn::kCaller, Turn::kWorker);
    if (abandon_) throw Abandoned{};
  };
  std::optional<RunSummary> summary;
  std::exception_ptr error;
  try {
    summary = RunScene(*scene_, options);
  } catch (const Abandoned&) {
  } catch (...) {
    error = std::current_exception();
  }
  std::unique_lock lock(mutex_);
  summary_ = std::move(summary);
  error_ = error;
  finished_ = true;
  turn_ = Turn::kCaller;
  turn_changed_.notify_all();
}

}  // namespace ancfnet::python
