#pragma once
/// @file Inputs that Debian's yaml-cpp 0.7 cannot parse in bounded time or memory, refused before
/// it sees them. Found by fuzzing the scene loader (fuzz/, docs/reliability.md).

#include <string>

namespace ancfnet {

/// Throws InputError "SOURCE:LINE:COLUMN: invalid YAML: ..." when a document of `yaml_text`
/// starts with ',' (after blank and comment lines, directives, the markers '---' and '...', a
/// byte-order mark, anchors and tags), when its root node is a flow collection or a quoted
/// scalar followed by ',' ("[1],", "{},", "'x',"), or when a ',' starts a line indented less than
/// its indented block root: on such a document yaml-cpp 0.7's LoadAll never returns and
/// allocates without bound (1.4 GB in 5 s for ",\n"). None is valid YAML: ',' separates the
/// entries of a flow collection. Then, for the malformed inputs no such rule foresees, it lets
/// yaml-cpp read the text in a child process (fork) and throws InputError "SOURCE: invalid YAML:
/// ..." when that does not finish within kYamlParseSeconds plus a second per MiB of CPU time (the
/// kernel stops the child); a child that cannot be started leaves the text to the caller's
/// parse.
void RefuseYamlThatHangsTheParser(const std::string& yaml_text, const std::string& source_name);

/// The CPU time yaml-cpp is given to read a scene, beyond a second per MiB of its text (s).
inline constexpr int kYamlParseSeconds = 2;

}  // namespace ancfnet
