#include "ancfnet/io/yaml_document.hpp"

#include <fmt/format.h>

#include <fstream>
#include <sstream>
#include <system_error>
#include <vector>

#include "ancfnet/common/error.hpp"
#include "ancfnet/io/yaml_hang_guard.hpp"

namespace ancfnet {
namespace {

// yaml-cpp's message with every byte outside printable ASCII written as \xNN: it quotes the
// offending character ("unknown escape character: X"), which in a binary file may be a line
// break or a control character, and the error must stay one readable line.
std::string EscapeUnprintable(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7f)
      out += c;
    else
      out += fmt::format("\\x{:02x}", byte);
  }
  return out;
}

}  // namespace

void ThrowYamlError(const std::string& source, const YAML::Exception& error) {
  const std::string why = EscapeUnprintable(error.msg);
  if (error.mark.is_null()) throw InputError(fmt::format("{}: invalid YAML: {}", source, why));
  throw InputError(fmt::format("{}:{}:{}: invalid YAML: {}", source, error.mark.line + 1,
                               error.mark.column + 1, why));
}

YAML::Node ParseYamlDocument(const std::string& yaml_text, const std::string& source_name,
                             std::string_view what) {
  RefuseYamlThatHangsTheParser(yaml_text, source_name);
  try {
    const std::vector<YAML::Node> documents = YAML::LoadAll(yaml_text);
    if (documents.size() > 1) {
      const YAML::Mark mark = documents[1].Mark();
      throw InputError(fmt::format(
          "{}:{}: a second YAML document (after '---'): a {} is one document, and the rest "
          "would be ignored",
          source_name, mark.is_null() ? 0 : mark.line + 1, what));
    }
    return documents.empty() ? YAML::Node() : documents.front();
  } catch (const YAML::Exception& error) {
    ThrowYamlError(source_name, error);
  }
}

std::string ReadInputFile(const std::filesystem::path& file, std::string_view what) {
  std::error_code error;
  std::ifstream in(file, std::ios::binary);
  if (!in || std::filesystem::is_directory(file, error))
    throw InputError(fmt::format("{}: cannot open {} file", file.string(), what));
  // Refused before reading: a device or pipe (/dev/zero would be read forever) and a file too
  // large to be an input file (meshes belong in mesh files).
  if (!std::filesystem::is_regular_file(file, error))
    throw InputError(
        fmt::format("{}: not a regular file (a {} is read from a file)", file.string(), what));
  if (const std::uintmax_t size = std::filesystem::file_size(file, error);
      !error && size > kMaxInputFileBytes)
    throw InputError(fmt::format("{}: {} bytes; a {} file may hold at most {} MiB", file.string(),
                                 size, what, kMaxInputFileBytes >> 20));
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace ancfnet
