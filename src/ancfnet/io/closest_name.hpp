#pragma once
/// @file "Did you mean …?" suggestions for misspelt keys and names.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ancfnet {

/// Levenshtein distance between `a` and `b`: the least number of single-character insertions,
/// deletions and substitutions that turn one into the other (Levenshtein 1966). O(|a| |b|) time.
std::size_t EditDistance(std::string_view a, std::string_view b);

/// The candidate nearest to `name` by EditDistance, when it is close enough to be a likely typo:
/// distance ≤ max(2, |name| / 3) and smaller than |name| (so that "x" does not suggest "y").
/// Ties go to the earliest candidate. std::nullopt when no candidate is that close.
std::optional<std::string> ClosestName(std::string_view name,
                                       const std::vector<std::string_view>& candidates);

/// A tail for an error message about the unknown `name`: "; did you mean 'NAME'?" for the closest
/// candidate, else "; LIST_LABEL: A, B, C" listing every candidate ("; LIST_LABEL: none" when there
/// are none). Example: SuggestName("stel", {"steel"}, "materials") is "; did you mean 'steel'?".
std::string SuggestName(std::string_view name, const std::vector<std::string_view>& candidates,
                        std::string_view list_label);

}  // namespace ancfnet
