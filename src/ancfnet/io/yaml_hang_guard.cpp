#include "ancfnet/io/yaml_hang_guard.hpp"

#include <fmt/format.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <cerrno>
#include <csignal>
#include <cstddef>
#include <string_view>

#include "ancfnet/common/error.hpp"

namespace ancfnet {
namespace {

bool IsBlank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// Walks a document's text character by character, with its line and column (from 1), to the
// point where its root node starts or ends.
class DocumentScanner {
 public:
  DocumentScanner(std::string_view text, std::string_view source) : text_(text), source_(source) {
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = line_start_ = 3;  // UTF-8 byte-order mark
  }

  void Run() {
    while (pos_ < text_.size()) ScanDocument();
  }

 private:
  bool AtLineStart() const { return pos_ == line_start_; }
  // A document marker ('---' or '...') at the start of the line, followed by a blank or the end.
  bool AtDocumentMarker() const {
    if (!AtLineStart()) return false;
    const std::string_view rest = text_.substr(pos_);
    if (rest.substr(0, 3) != "---" && rest.substr(0, 3) != "...") return false;
    return rest.size() == 3 || IsBlank(rest[3]) || rest[3] == '\n';
  }
  void Advance() {
    if (text_[pos_] == '\n') {
      ++line_;
      line_start_ = pos_ + 1;
    }
    ++pos_;
  }
  void SkipToLineEnd() {
    while (pos_ < text_.size() && text_[pos_] != '\n') Advance();
  }
  [[noreturn]] void RefuseComma(const char* where) const {
    throw InputError(fmt::format(
        "{}:{}:{}: invalid YAML: a ',' {} (it separates the entries of a flow collection, "
        "[a, b] or {{a: b, c: d}})",
        source_, line_, pos_ - line_start_ + 1, where));
  }

  // From a document's start (or a marker) to the next marker: refuses a document whose root
  // node starts with ',' or is a flow node followed by ',' (yaml-cpp 0.7 never returns on
  // either), and skips the rest.
  void ScanDocument() {
    if (AtDocumentMarker()) pos_ += 3;
    if (!SkipToRoot()) return;
    const char first = text_[pos_];
    if (first == ',') RefuseComma("cannot start a document");
    if (first == '[' || first == '{' || first == '"' || first == '\'') {
      if (!SkipFlowRoot()) return;
      if (!SkipToRoot()) return;  // the next significant character
      if (text_[pos_] == ',') RefuseComma("cannot follow a document's root node");
    } else {
      // A block root indented by n ends at the first line indented less (nothing inside it can
      // be): a ',' there is outside every node.
      const std::size_t indent = pos_ - line_start_;
      SkipLine();
      while (indent > 0 && pos_ < text_.size() && !AtDocumentMarker()) {
        std::size_t i = pos_;
        while (i < text_.size() && IsBlank(text_[i])) ++i;
        if (i < text_.size() && text_[i] != '\n' && text_[i] != '#' && i - pos_ < indent) {
          pos_ = i;
          if (text_[pos_] == ',') RefuseComma("cannot follow a document's root node");
          break;
        }
        SkipLine();
      }
    }
    while (pos_ < text_.size() && !AtDocumentMarker()) SkipLine();
  }
  void SkipLine() {
    SkipToLineEnd();
    if (pos_ < text_.size()) Advance();
  }
  // To the next character of a node, past blanks, line ends, comments, directives ('%' at a
  // line's start), anchors (&a) and tags (!t), which yaml-cpp ends at a flow indicator ("&a,"
  // starts with ','). False at the end of the document.
  bool SkipToRoot() {
    while (pos_ < text_.size()) {
      if (AtDocumentMarker()) return false;
      const char c = text_[pos_];
      if (IsBlank(c) || c == '\n') {
        Advance();
      } else if (c == '#' || (c == '%' && AtLineStart())) {
        SkipToLineEnd();
      } else if (c == '&' || c == '!') {
        while (pos_ < text_.size() && !IsBlank(text_[pos_]) && text_[pos_] != '\n' &&
               text_[pos_] != ',')
          Advance();
      } else {
        return true;
      }
    }
    return false;
  }
  // Past a flow collection or quoted scalar that starts at pos_, its quotes and nested brackets
  // matched; false when the document ends first.
  bool SkipFlowRoot() {
    int depth = 0;
    char quote = 0;
    while (pos_ < text_.size()) {
      if (quote == 0 && AtDocumentMarker()) return false;
      const char c = text_[pos_];
      const bool after_blank = pos_ == line_start_ || IsBlank(text_[pos_ - 1]);
      Advance();
      if (quote == '"') {
        if (c == '\\' && pos_ < text_.size()) Advance();  // an escaped character
        if (c == '"') quote = 0;
      } else if (quote == '\'') {
        if (c == '\'' && pos_ < text_.size() && text_[pos_] == '\'')
          Advance();  // '' inside single quotes
        else if (c == '\'')
          quote = 0;
      } else if (c == '"' || c == '\'') {
        quote = c;
      } else if (c == '#' && after_blank) {
        SkipToLineEnd();
      } else if (c == '[' || c == '{') {
        ++depth;
      } else if (c == ']' || c == '}') {
        --depth;
      }
      if (quote == 0 && depth <= 0) return true;
    }
    return false;
  }

  std::string_view text_;
  std::string_view source_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
  std::size_t line_start_ = 0;
};

// yaml-cpp reads the text in a child process, which the kernel stops when it has used up its
// CPU time (RLIMIT_CPU: SIGXCPU at the limit, SIGKILL a second later). CPU time, not wall-clock
// time, so that a loaded machine does not refuse a good scene.
void RequireYamlReaderToFinish(const std::string& yaml_text, const std::string& source_name) {
  const int limit = kYamlParseSeconds + static_cast<int>(yaml_text.size() >> 20);
  const pid_t child = ::fork();
  if (child < 0) return;
  if (child == 0) {
    const rlimit no_core_file{0, 0};
    ::setrlimit(RLIMIT_CORE, &no_core_file);
    const rlimit cpu{static_cast<rlim_t>(limit), static_cast<rlim_t>(limit) + 1};
    ::setrlimit(RLIMIT_CPU, &cpu);
    // The default action (the parent's handler, a fuzzer's for one, would not stop the child).
    ::signal(SIGXCPU, SIG_DFL);
    try {
      YAML::LoadAll(yaml_text);
    } catch (...) {
    }
    ::_exit(0);  // no atexit handlers, no flush of the parent's buffers
  }
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFSIGNALED(status) && (WTERMSIG(status) == SIGXCPU || WTERMSIG(status) == SIGKILL))
    throw InputError(fmt::format(
        "{}: invalid YAML: the YAML reader did not finish within {} s of CPU time (yaml-cpp 0.7 "
        "loops on some malformed text); check the file's syntax",
        source_name, limit));
}

}  // namespace

void RefuseYamlThatHangsTheParser(const std::string& yaml_text, const std::string& source_name) {
  DocumentScanner(yaml_text, source_name).Run();
  RequireYamlReaderToFinish(yaml_text, source_name);
}

}  // namespace ancfnet
