#pragma once
/// @file Reading one YAML document from a file or a string, with the checks every input file of
/// ancfnet gets (scene files, study files): a bounded size, no device or pipe, no input that
/// hangs yaml-cpp, exactly one document, and yaml-cpp's errors as one line with file and line.

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace ancfnet {

/// The largest input file read (bytes): 64 MiB.
inline constexpr std::uintmax_t kMaxInputFileBytes = std::uintmax_t{64} << 20;

/// The text of `file`, a `what` ("scene", "study"). Throws InputError "FILE: cannot open WHAT
/// file" when it cannot be read, and refuses at once (before reading) a file that is not a
/// regular file (a device, a pipe) or holds more than kMaxInputFileBytes.
std::string ReadInputFile(const std::filesystem::path& file, std::string_view what);

/// The one YAML document of `yaml_text`, a `what` ("scene", "study"; a null node when the text
/// holds none); `source_name` names it in messages. Throws InputError "SOURCE:LINE:COLUMN:
/// invalid YAML: …" for malformed YAML (RefuseYamlThatHangsTheParser first), and "SOURCE:LINE: a
/// second YAML document …" for one after '---'.
YAML::Node ParseYamlDocument(const std::string& yaml_text, const std::string& source_name,
                             std::string_view what);

/// Throws `error` as InputError "SOURCE:LINE:COLUMN: invalid YAML: …", every byte outside
/// printable ASCII written as \xNN so that the message stays one readable line.
[[noreturn]] void ThrowYamlError(const std::string& source, const YAML::Exception& error);

}  // namespace ancfnet
