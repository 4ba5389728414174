#include "tool_script.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "ancfnet/common/error.hpp"

namespace ancfnet {
namespace {

std::string FromEnvironment(const char* variable, const std::string& fallback) {
  const char* value = std::getenv(variable);
  return value != nullptr && *value != '\0' ? std::string(value) : fallback;
}

}  // namespace

std::filesystem::path FindToolScript(const std::string& name) {
  const std::filesystem::path folder = FromEnvironment("ANCFNET_TOOLS_DIR", ANCFNET_TOOLS_DIR);
  const std::filesystem::path script = folder / name;
  if (!std::filesystem::is_regular_file(script))
    throw InputError(fmt::format(
        "cannot find the script {} (set ANCFNET_TOOLS_DIR to the folder tools/ of ancfnet's "
        "sources; built with {})",
        script.string(), ANCFNET_TOOLS_DIR));
  return script;
}

void ExecToolScript(const std::filesystem::path& script,
                    const std::vector<std::string>& arguments) {
  const std::string python = FromEnvironment("ANCFNET_PYTHON", ANCFNET_PYTHON);
  std::vector<std::string> words = {python, script.string()};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  std::fflush(stdout);
  std::fflush(stderr);
  execv(python.c_str(), argv.data());
  throw InputError(
      fmt::format("cannot run {} ({}): install Debian's python3-matplotlib "
                  "(scripts/install-deps.sh) or set ANCFNET_PYTHON",
                  python, std::strerror(errno)));
}

}  // namespace ancfnet
