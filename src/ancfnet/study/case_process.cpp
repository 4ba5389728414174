#include "ancfnet/study/case_process.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/prctl.h>
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
  // Opened before fork: between fork and exec the child makes only async-signal-safe calls.
  const int input = open("/dev/null", O_RDONLY | O_CLOEXEC);
  const int output = open("/dev/null", O_WRONLY | O_CLOEXEC);
  const int messages =
      open((folder / "stderr.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  const pid_t parent = getpid();
  const pid_t pid = input < 0 || output < 0 || messages < 0 ? -1 : fork();
  if (pid == 0) {
    // A process group of its own: a Ctrl-C at the terminal reaches the study alone, which
    // passes it on once (a second SIGINT would end the run without its outputs). SIGTERM when
    // the study dies (killed), so that no orphaned case writes into a folder a resumed study
    // runs again.
    setpgid(0, 0);
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (getppid() != parent) _exit(kExitInterruptedBySigterm);
    dup2(input, STDIN_FILENO);
    dup2(output, STDOUT_FILENO);
    dup2(messages, STDERR_FILENO);
    execv(argv[0], argv.data());
    _exit(127);
  }
  const int error_number = errno;
  for (const int descriptor : {input, output, messages})
    if (descriptor >= 0) close(descriptor);
  if (pid < 0)
    throw InputError(fmt::format("cannot start {} for case {}: {}", launcher.executable.string(),
                                 index, std::strerror(error_number)));
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
