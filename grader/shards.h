// shards.h: a class graded in parts on several machines, and the parts joined (docs/grading.md,
// "A class larger than one machine"). A submission's part follows from its name alone, so it
// is always in the same part; each report folder keeps a record of what it graded
// (grading.json), from which the parts are joined into the report one run over the class gives,
// but for the measured times.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "grader/report.h"

namespace jello::grader {

// "K/N": part K (1 to N) of N; throws std::invalid_argument with the option's words otherwise.
struct Shard {
  int part = 1, parts = 1;
};
Shard parseShard(const std::string& text);

// Whether the submission named `name` is in `shard`: by a hash of the name (FNV-1a), so parts
// are of about equal size and a name is always in the same one.
bool inShard(const std::string& name, const Shard& shard);

// The record of a report folder: every submission's grades, words, notes, log and time, the
// seed and --strict.
std::string gradedRecord(const std::vector<Graded>& graded, std::uint64_t seed, bool strict);
struct GradedRecord {
  std::vector<Graded> graded;
  std::uint64_t seed = 0;
  bool strict = false;
};
// Reads `dir`/grading.json; throws std::runtime_error naming the file when it is not one.
GradedRecord readGradedRecord(const std::string& dir);

constexpr const char* kRecordName = "grading.json";

}  // namespace jello::grader
