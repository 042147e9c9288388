// core/nearest.h: the name a mistyped one most likely meant, for the command lines' options and a
// scene file's keys alike ("did you mean ...?").
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

namespace jello {

// Edits (insertions, deletions, substitutions) from a to b: how far a typed name is from another.
inline std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// The one of `candidates` a mistyped `name` most likely meant ("--step" -> "--steps", "gravty" ->
// "gravity"), or "" when none is near: one edit in four characters (at most two; "--fast" is not
// "--fps"), or one name the start of the other (a name over 3 characters); the first of the
// nearest.
inline std::string nearestName(const std::string& name,
                               const std::vector<std::string>& candidates) {
  const std::size_t mostEdits = std::clamp<std::size_t>(name.size() / 4, 1, 2);
  std::string best;
  std::size_t bestEdits = mostEdits + 1;
  for (const std::string& candidate : candidates) {
    const bool prefix =
        name.size() > 3 && (candidate.rfind(name, 0) == 0 || name.rfind(candidate, 0) == 0);
    const std::size_t edits = prefix ? 1 : editDistance(name, candidate);
    if (edits < bestEdits) best = candidate, bestEdits = edits;
  }
  return best;
}

}  // namespace jello
