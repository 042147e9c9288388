// io/worldparser.cpp: the strict world-file reader (docs/world-format.md), a line at a time.
//
// The reader is line-oriented: every record of the table sits on its own line, as the course's
// files and createWorld write them, so an error can name the exact line and field. Blank lines
// are skipped; CR before LF is whitespace. Numbers go through std::from_chars, which is exact
// (correctly rounded) and fast, and which, unlike strtod, ignores the locale.

#include "io/worldparser.h"

#include <array>
#include <charconv>
#include <cmath>
#include <string>

#include "core/memory.h"
#include "io/input.h"
#include "model/model.h"

namespace jello {

namespace {

constexpr int kMaxTokensKept = 8;
constexpr std::size_t kMaxIntegratorNameLength = 16;  // longer than any name in the table
// The shortest possible field line, "0 0 0\n": a file shorter than R^3 of these cannot hold
// the field it announces, so it is refused before any memory is set aside for it.
constexpr std::size_t kShortestFieldLine = 6;

constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// A CR with more text after it on the same line: the line ends are CR alone, not CRLF (whose
// CR is the last character before the LF, and whitespace).
bool hasBareCarriageReturn(std::string_view line) {
  std::size_t cr = line.find('\r');
  if (cr == std::string_view::npos) return false;
  for (std::size_t i = cr + 1; i < line.size(); ++i)
    if (!isSpace(line[i])) return true;
  return false;
}

class Parser {
 public:
  Parser(LineSource& source, const std::string& name) : source_(source), name_(name) {}

  [[noreturn]] void fail(int line, const std::string& what, const std::string& field) const {
    throw InputError(name_ + ":" + std::to_string(line) + ": " + what + " (" + field + ")");
  }

  // Moves to the next non-blank line and splits it into tokens. Returns false at end of file;
  // fails on a line that no world file holds (too long, or not text).
  bool nextLine(const std::string& field) {
    std::string_view line;
    for (;;) {
      LineSource::Status status = LineSource::Status::End;
      try {
        status = source_.next(&line);
      } catch (const LineSource::Stalled&) {
        fail(line_ + 1,
             "nothing arrived for " + std::to_string(kInputWaitSeconds) +
                 " s: the writer stopped sending before the world's end",
             field);
      }
      ++line_;
      count_ = 0;
      if (status == LineSource::Status::End) return false;
      // Windows editors start a UTF-8 file with a byte order mark; it is no part of the text.
      if (line_ == 1 && line.substr(0, kUtf8Bom.size()) == kUtf8Bom)
        line.remove_prefix(kUtf8Bom.size());
      split(line, field);
      // A CR-only file (classic Mac OS) is one long line to a reader that splits at LF.
      if (hasBareCarriageReturn(line)) {
        fail(line_,
             "lines end with CR only (classic Mac OS line ends): convert the file to LF or CRLF "
             "line ends",
             field);
      }
      if (status == LineSource::Status::TooLong) {
        fail(line_,
             "line is longer than " + std::to_string(LineSource::kMaxLineLength) +
                 " characters: not a world file",
             field);
      }
      if (count_ > 0) return true;
    }
  }

  // Splits `line` into tokens at whitespace; fails on a byte that no text holds.
  void split(std::string_view line, const std::string& field) {
    std::size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && isSpace(line[i])) ++i;
      if (i == line.size()) break;
      std::size_t start = i;
      while (i < line.size() && !isSpace(line[i])) {
        const unsigned char c = static_cast<unsigned char>(line[i]);
        if (c < 0x20 || c >= 0x7f) {
          char text[96];
          std::snprintf(text, sizeof text,
                        "byte 0x%02x in column %zu: not a text file, not a world file", c, i + 1);
          fail(line_, text, field);
        }
        ++i;
      }
      if (count_ < kMaxTokensKept) tokens_[count_] = line.substr(start, i - start);
      ++count_;
    }
  }

  // Reads the next record, which must hold exactly `count` tokens.
  void record(int count, const std::string& field) {
    if (!nextLine(field)) {
      if (records_ == 0) fail(1, "the file is empty", field);
      fail(line_, "file ends early, expected " + what(count), field);
    }
    ++records_;
    if (count_ != count) {
      fail(line_, "expected " + what(count) + ", found " + std::to_string(count_), field);
    }
  }

  std::string_view token(int i) const { return tokens_[i]; }
  int line() const { return line_; }
  LineSource& source() { return source_; }

  // Token i as a T, the whole token and nothing else; `kind` names T in messages.
  template <class T>
  T parsed(int i, const std::string& field, const char* kind) const {
    std::string_view t = tokens_[i];
    T value{};
    auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
    if (ec == std::errc::result_out_of_range)
      fail(line_, "'" + str(t) + "' is out of range", field);
    if (ec != std::errc() || end != t.data() + t.size()) {
      fail(line_, "'" + str(t) + "' is not " + kind, field);
    }
    return value;
  }

  double number(int i, const std::string& field) const {
    double value = parsed<double>(i, field, "a number");
    if (std::isnan(value)) fail(line_, "NaN is not allowed", field);
    if (std::isinf(value)) fail(line_, "infinity is not allowed", field);
    return value;
  }

  int integer(int i, const std::string& field) const {
    return parsed<int>(i, field, "a whole number");
  }

  double positive(int i, const std::string& field) const {
    double value = number(i, field);
    if (!(value > 0)) fail(line_, "must be > 0, got " + str(tokens_[i]), field);
    return value;
  }

  double nonNegative(int i, const std::string& field) const {
    double value = number(i, field);
    if (value < 0) fail(line_, "must be >= 0, got " + str(tokens_[i]), field);
    return value;
  }

  static std::string str(std::string_view s) { return std::string(s); }

 private:
  static std::string what(int count) {
    return count == 1 ? std::string("1 value") : std::to_string(count) + " numbers";
  }

  LineSource& source_;
  const std::string& name_;
  int line_ = 0;
  long long records_ = 0;
  int count_ = 0;
  std::array<std::string_view, kMaxTokensKept> tokens_{};
};

void readPoints(Parser& in, double* points, const std::string& what) {
  for (int q = 0; q < kNumPoints; ++q) {
    std::string field = what + latticeLabel(q);
    in.record(3, field);
    for (int axis = 0; axis < 3; ++axis) points[coordIndex(q, axis)] = in.number(axis, field);
  }
}

template <class T>
bool parseExactly(std::string_view text, T* out, std::string* why) {
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), *out);
  if (ec == std::errc::result_out_of_range)
    *why = "is out of range";
  else if (ec != std::errc() || end != text.data() + text.size())
    *why = "is not a number";
  else
    return true;
  return false;
}

}  // namespace

bool parseWorldNumber(std::string_view text, double* out, std::string* why) {
  if (!parseExactly(text, out, why)) return false;
  if (std::isfinite(*out)) return true;
  *why = "is not finite";
  return false;
}

bool parseWorldInteger(std::string_view text, long long* out, std::string* why) {
  if (parseExactly(text, out, why)) return true;
  if (*why == "is not a number") *why = "is not a whole number";
  return false;
}

namespace {

// Doubles set aside at first for a field whose input has no known size (a pipe): the vector
// then grows with what actually arrives, not with what the resolution line claims.
constexpr std::size_t kUnknownSizeReserve = 3 << 16;

void readIntegrator(Parser& in, RunSettings& w) {
  in.record(1, "integrator");
  std::string_view integrator = in.token(0);
  if (integrator.size() > kMaxIntegratorNameLength) {
    in.fail(in.line(),
            "integrator name is too long (" + std::to_string(integrator.size()) + " characters)",
            "integrator");
  }
  if (!parseIntegratorName(integrator, &w.integrator)) {
    in.fail(
        in.line(),
        "unknown integrator '" + Parser::str(integrator) + "', expected " + integratorNameList(),
        "integrator");
  }
}

// dt n.
void readSteps(Parser& in, RunSettings& run) {
  in.record(2, "dt n");
  run.dt = in.positive(0, "dt");
  run.n = in.integer(1, "n");
  if (run.n < 1) in.fail(in.line(), "must be >= 1, got " + Parser::str(in.token(1)), "n");
}

// The springs' four constants, and the mass.
void readParameters(Parser& in, World& w) {
  in.record(4, "kElastic dElastic kCollision dCollision");
  w.kElastic = in.nonNegative(0, "kElastic");
  w.dElastic = in.nonNegative(1, "dElastic");
  w.kCollision = in.nonNegative(2, "kCollision");
  w.dCollision = in.nonNegative(3, "dCollision");

  in.record(1, "mass");
  w.mass = in.positive(0, "mass");
}

void readPlane(Parser& in, World& w) {
  in.record(1, "incPlanePresent");
  int flag = in.integer(0, "incPlanePresent");
  if (flag != 0 && flag != 1) {
    in.fail(in.line(), "must be 0 or 1, got " + Parser::str(in.token(0)), "incPlanePresent");
  }
  w.hasPlane = flag == 1;
  if (w.hasPlane) {
    in.record(4, "plane a b c d");
    w.plane = {in.number(0, "plane a"), in.number(1, "plane b"), in.number(2, "plane c"),
               in.number(3, "plane d")};
    if (!hasNormal(w.plane)) {
      in.fail(in.line(), "the plane's normal (a,b,c) is zero", "plane a b c");
    }
    // A normal of any size is simulated (normalised by a power of two); an offset too large for it
    // is not.
    if (std::string why = planeProblem(w.plane); !why.empty()) in.fail(in.line(), why, "plane d");
  }
}

// The resolution line: R, refused when the rest of the file or the memory cannot hold R^3 nodes.
int readResolution(Parser& in) {
  in.record(1, "resolution");
  int r = in.integer(0, "resolution");
  if (r < 0) in.fail(in.line(), "must be >= 0, got " + Parser::str(in.token(0)), "resolution");
  if (r > kMaxResolution) {
    in.fail(in.line(),
            std::to_string(r) + " is too large to hold (at most " + std::to_string(kMaxResolution) +
                ")",
            "resolution");
  }
  std::size_t nodes = static_cast<std::size_t>(r) * r * r;
  if (in.source().remainingKnown() && nodes * kShortestFieldLine > in.source().remainingBytes()) {
    in.fail(in.line(),
            std::to_string(r) + " needs " + std::to_string(nodes) +
                " field lines, more than the rest of the file can hold",
            "resolution");
  }
  // Refused before anything is set aside for it, not by std::bad_alloc halfway through.
  if (r > 0) {
    const std::uint64_t needed = worldMemoryNeed(r, worldUse(), !in.source().remainingKnown()),
                        available = availableMemory();
    if (needed > available)
      in.fail(in.line(), notEnoughMemoryMessage(needed, available), "resolution");
  }
  return r;
}

void readField(Parser& in, ForceField& field) {
  const int r = readResolution(in);
  const std::size_t nodes = static_cast<std::size_t>(r) * r * r;
  const bool streamed = !in.source().remainingKnown();
  field.resolution = r;
  std::vector<double>& forces = field.forces;
  forces.reserve(streamed ? std::min(3 * nodes, kUnknownSizeReserve) : 3 * nodes);
  for (std::size_t node = 0; node < nodes; ++node) {
    std::size_t i = node / (static_cast<std::size_t>(r) * r), j = (node / r) % r, k = node % r;
    std::string name = "force field node (" + std::to_string(i) + "," + std::to_string(j) + "," +
                       std::to_string(k) + ")";
    in.record(3, name);
    // Grown by doubling, but never beyond the announced size (worldMemoryNeed counts on it).
    if (forces.capacity() - forces.size() < 3)
      forces.reserve(std::min(3 * nodes, 2 * forces.capacity() + 3));
    for (int axis = 0; axis < 3; ++axis) forces.push_back(in.number(axis, name));
  }
}

}  // namespace

WorldFile parseLines(LineSource& source, const std::string& name) {
  Parser in(source, name);
  WorldFile result;
  readIntegrator(in, result.run);
  readSteps(in, result.run);
  readParameters(in, result.world);
  readPlane(in, result.world);
  readField(in, result.world.field);
  readPoints(in, result.state.p(), "position p");
  readPoints(in, result.state.v(), "velocity v");

  if (in.nextLine("trailing garbage")) {
    in.fail(in.line(), "unexpected '" + Parser::str(in.token(0)) + "' after the 512 velocities",
            "trailing garbage");
  }
  return result;
}

}  // namespace jello
