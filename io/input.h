// io/input.h: world files (.w, docs/world-format.md): the reader, the writer, and the rules a
// world in memory must keep to be written. The course's input.cpp (at the root) reads and writes
// them; the line parser is io/worldparser.cpp, the rules io/worldcheck.cpp.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/inputerror.h"
#include "model/world.h"

namespace jello {

// A world file: its physics, its run settings and its state.
struct WorldFile {
  World world;
  RunSettings run;
  State state;
  std::vector<std::string> inputs;  // the files a scene read besides itself (Reader::inputs)
};

// Why a world in memory is one the reader would refuse (the rules of docs/world-format.md on its
// values), by the part of the world at fault, so that a program that makes worlds can say which of
// its inputs is to blame.
struct WorldProblem {
  enum class Part { Parameters, Plane, Field, Position, Velocity };
  Part part = Part::Parameters;
  std::size_t index = 0;  // the field node (Field) or the point (Position, Velocity)
  // One line, e.g. "the velocity of point [0][0][0] is (inf, 0, 0) m/s, not finite".
  std::string what;
};
// The first problem of `world` and `state` (which holds the world's body's points), or none when
// formatWorld of them reads back.
std::optional<WorldProblem> findWorldProblem(const World& world, const RunSettings& run,
                                             const State& state);
inline std::optional<WorldProblem> findWorldProblem(const WorldFile& file) {
  return findWorldProblem(file.world, file.run, file.state);
}

// The number grammar of world files, which the command lines share: a decimal number exactly as
// std::from_chars reads it (no hex, no leading '+' or space), rounded once to the nearest
// double. False with *why set ("is not a number", "is out of range", "is not finite") otherwise.
bool parseWorldNumber(std::string_view text, double* out, std::string* why);
// A whole number in the same grammar (decimal digits, an optional '-').
bool parseWorldInteger(std::string_view text, long long* out, std::string* why);

// Appends the shortest text that reads back as `value` exactly (std::to_chars): how world files
// and the reader's messages write numbers.
void appendNumber(std::string& out, double value);

// Parses the text of a world file; `name` is used in error messages. Throws InputError.
WorldFile parseWorld(std::string_view text, const std::string& name);
// Reads and parses a world file. Throws InputError (also for unreadable files).
WorldFile readWorldFile(const std::string& path);

// The text of a world file, numbers in shortest round-trip form: parseWorld of it gives back
// bit-identical values.
std::string formatWorld(const World& world, const RunSettings& run, const State& state);
inline std::string formatWorld(const WorldFile& file) {
  return formatWorld(file.world, file.run, file.state);
}
// The same text handed to `write` in blocks of about 64 KB, in order: a world with a large field
// (R = 512: gigabytes of text) is written without its whole text in memory.
void formatWorldInBlocks(const World& world, const RunSettings& run, const State& state,
                         const std::function<void(std::string_view)>& write);
// Writes the world to `path` in blocks under the rules of output.h: whole, never over anything
// that is not a regular file; over an existing regular file only with `overwrite` (without it
// the check and the write are one atomic step). Throws OutputError (a std::runtime_error) with a
// one-line message on failure.
void writeWorldFile(const std::string& path, const World& world, const RunSettings& run,
                    const State& state, bool overwrite = true);

}  // namespace jello
