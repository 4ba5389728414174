#pragma once
/// @file The Python scripts shipped in tools/ (plots, report, animation), found and run by the
/// command-line tool.

#include <filesystem>
#include <string>
#include <vector>

namespace ancfnet {

/// The path of tools/`name`: in $ANCFNET_TOOLS_DIR when that is set, else in the folder
/// configured at build time (the source tree's tools/). Throws InputError naming both when the
/// script is not there.
std::filesystem::path FindToolScript(const std::string& name);

/// Replaces the process by the Python interpreter ($ANCFNET_PYTHON, else the one configured at
/// build time, Debian's /usr/bin/python3) running `script` with `arguments`; the script's exit
/// code becomes the tool's. Throws InputError when the interpreter cannot be started.
[[noreturn]] void ExecToolScript(const std::filesystem::path& script,
                                 const std::vector<std::string>& arguments);

}  // namespace ancfnet
