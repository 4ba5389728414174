#include "ancfnet/study/case_process.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <system_error>

#include "ancfnet/common/error.hpp"
#include "ancfnet/common/interrupt.hpp"

extern char** environ;

namespace ancfnet {
namespace {

// Exit codes of `ancfnet run` stopped by SIGINT or SIGTERM (apps/ancfnet/main.cpp).
constexpr int kExitInterruptedBySigint = 130;
constexpr int kExitInterruptedBySigterm = 143;

// The last non-empty line of the case's stderr.txt, without the tool's "ancfnet: " prefix.
std::string LastMessage(const std::filesystem::path& folder) {
  std::ifstream file(folder / "stderr.txt");
  std::string line, last;
  while (std::getline(file, line)) {
    line.erase(std::remove(line.begin(), line.end(), '\r'), line.end());
    if (!line.empty()) last = line;
  }
  constexpr std::string_view kPrefix = "ancfnet: ";
  if (last.starts_with(kPrefix)) last.erase(0, kPrefix.size());
  return last;
}

// The message of a failed run's summary.json; empty when there is none.
std::string SummaryMessage(const std::filesystem::path& folder) {
  std::ifstream file(folder / "summary.json");
  const nlohmann::json json = nlohmann::json::parse(file, nullptr, /*allow_exceptions=*/false);
  if (!json.is_object() || !json.contains("message") || !json["message"].is_string()) return "";
  return json["message"].get<std::string>();
}

}  // namespace

pid_t StartCase(const CaseLauncher& launcher, const Study& study, std::size_t index,
                const std::vector<double>& values) {
  const std::filesystem::path folder = CaseFolder(launcher.study_dir, index);
  std::error_code error;
  std::filesystem::remove_all(folder, error);
  std::filesystem::create_directories(folder, error);
  if (error)
    throw InputError(
        fmt::format("cannot create the case folder {}: {}", folder.string(), error.message()));
  const std::filesystem::path scene = folder / "scene.yaml";
  {
    std::ofstream file(scene);
    file << study.MakeCaseScene(values);
    file.close();
    if (!file) throw InputError(fmt::format("cannot write {}", scene.string()));
  }
  const std::filesystem::path scene_directory =
      std::filesystem::absolute(study.scene_file).parent_path();
  std::vector<std::string> words = {launcher.executable.string(),
                                    "run",
                                    scene.string(),
                                    "-o",
                                    folder.string(),
                                    "-q",
                                    "--scene-dir",
                                    scene_directory.string()};
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  const std::string messages = (folder / "stderr.txt").string();
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, messages.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  // A process group of its own: a Ctrl-C at the terminal reaches the study alone, which passes
  // it on once (a second SIGINT would end the run without its outputs).
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
  posix_spawnattr_setpgroup(&attributes, 0);
  pid_t pid = 0;
  const int failed = posix_spawn(&pid, argv[0], &actions, &attributes, argv.data(), environ);
  posix_spawnattr_destroy(&attributes);
  posix_spawn_file_actions_destroy(&actions);
  if (failed != 0)
    throw InputError(fmt::format("cannot start {} for case {}: {}", launcher.executable.string(),
                                 index, std::strerror(failed)));
  return pid;
}

std::optional<CaseResult> FinishCase(const CaseLauncher& launcher, std::size_t index,
                                     const std::vector<double>& values, int wait_status) {
  const std::filesystem::path folder = CaseFolder(launcher.study_dir, index);
  CaseResult result;
  result.index = index;
  result.values = values;
  if (WIFEXITED(wait_status)) {
    const int code = WEXITSTATUS(wait_status);
    if (code == kExitInterruptedBySigint || code == kExitInterruptedBySigterm) return std::nullopt;
    result.ok = code == 0;
    if (!result.ok) {
      result.reason = SummaryMessage(folder);
      if (result.reason.empty()) result.reason = LastMessage(folder);
      if (result.reason.empty()) result.reason = fmt::format("exit code {}", code);
      // Paths in the message relative to DIR: the table does not depend on where DIR is.
      const std::string prefix = (launcher.study_dir / "").string();
      for (std::size_t at; (at = result.reason.find(prefix)) != std::string::npos;)
        result.reason.erase(at, prefix.size());
    }
  } else {
    const int signal = WIFSIGNALED(wait_status) ? WTERMSIG(wait_status) : 0;
    if (signal == SIGINT || signal == SIGTERM) return std::nullopt;
    result.reason = fmt::format("crashed: signal {} ({})", signal, strsignal(signal));
  }
  WriteCaseResult(launcher.study_dir, result);
  return result;
}

std::pair<pid_t, int> WaitForCase(const std::vector<pid_t>& running, bool* interrupt_passed_on) {
  while (true) {
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid > 0 && std::find(running.begin(), running.end(), pid) != running.end())
      return {pid, status};
    if (pid < 0 && errno != EINTR)
      throw std::runtime_error(fmt::format("waitpid: {}", std::strerror(errno)));
    if (const int signal = InterruptRequested(); signal != 0 && !*interrupt_passed_on) {
      for (const pid_t child : running) kill(child, signal);
      *interrupt_passed_on = true;
    }
  }
}

std::optional<CaseResult> RunCase(const CaseLauncher& launcher, const Study& study,
                                  std::size_t index, const std::vector<double>& values) {
  const pid_t pid = StartCase(launcher, study, index, values);
  bool interrupt_passed_on = false;
  const int status = WaitForCase({pid}, &interrupt_passed_on).second;
  return FinishCase(launcher, index, values, status);
}

}  // namespace ancfnet
