#pragma once
/// @file Inputs that Debian's yaml-cpp 0.7 cannot parse in bounded time or memory, refused before
/// it sees them. Found by fuzzing the scene loader (fuzz/, docs/reliability.md).

#include <string>

namespace ancfnet {

/// Throws InputError "SOURCE:LINE:COLUMN: invalid YAML: ..." when a document of `yaml_text`
/// starts with ',' (after blank and comment lines, directives, the markers '---' and '...', a
/// byte-order mark, anchors and tags), or when its root node is a flow collection or a quoted
/// scalar followed by ',' ("[1],", "{},", "'x',"): on such a document yaml-cpp 0.7's LoadAll
/// never returns and allocates without bound (1.4 GB in 5 s for ",\n"). Neither is valid YAML:
/// ',' separates the entries of a flow collection.
void RefuseYamlThatHangsTheParser(const std::string& yaml_text, const std::string& source_name);

}  // namespace ancfnet
