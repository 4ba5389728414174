#include "ancfnet/io/yaml_hang_guard.hpp"

#include <fmt/format.h>

#include <cstddef>
#include <string_view>

#include "ancfnet/common/error.hpp"

namespace ancfnet {
namespace {

bool IsBlank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// A document marker ('---' or '...') at the start of `line`, followed by a blank or the end.
bool StartsWithDocumentMarker(std::string_view line) {
  if (line.size() < 3 || (line.substr(0, 3) != "---" && line.substr(0, 3) != "...")) return false;
  return line.size() == 3 || IsBlank(line[3]);
}

}  // namespace

void RefuseYamlThatHangsTheParser(const std::string& yaml_text, const std::string& source_name) {
  std::string_view text(yaml_text);
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // UTF-8 byte-order mark
  bool at_document_start = true;
  std::size_t line_number = 0;
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    const std::string_view line = text.substr(0, end);
    text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
    ++line_number;
    std::size_t i = 0;
    if (StartsWithDocumentMarker(line)) {
      at_document_start = true;
      i = 3;
    } else if (!at_document_start || (!line.empty() && line[0] == '%')) {
      continue;  // inside a document, or a directive before one
    }
    // The rest of the line up to the document's first node: blanks, anchors (&a) and tags (!t).
    while (i < line.size()) {
      if (IsBlank(line[i])) {
        ++i;
      } else if (line[i] == '&' || line[i] == '!') {
        // yaml-cpp ends an anchor's name (and a tag) at a flow indicator: "&a," starts with ','.
        while (i < line.size() && !IsBlank(line[i]) && line[i] != ',') ++i;
      } else {
        break;
      }
    }
    if (i == line.size() || line[i] == '#') continue;  // nothing yet: the start is further on
    if (line[i] == ',')
      throw InputError(fmt::format(
          "{}:{}:{}: invalid YAML: a document cannot start with ',' (it separates the entries "
          "of a flow collection, [a, b] or {{a: b, c: d}})",
          source_name, line_number, i + 1));
    at_document_start = false;
  }
}

}  // namespace ancfnet
