// input.cpp: the strict world-file reader and the round-trip writer (docs/world-format.md).
//
// The reader is line-oriented: every record of the table sits on its own line, as the course's
// files and createWorld write them, so an error can name the exact line and field. Blank lines
// are skipped; CR before LF is whitespace. Numbers go through std::from_chars, which is exact
// (correctly rounded) and fast, and which, unlike strtod, ignores the locale.

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <system_error>

#include "core/assert.h"
#include "core/memory.h"
#include "core/output.h"
#include "physics.h"
#include "world.h"

namespace jello {

namespace {

constexpr std::size_t kMaxIntegratorNameLength = 16;  // longer than any name in the table
// The shortest possible field line, "0 0 0\n": a file shorter than R^3 of these cannot hold
// the field it announces, so it is refused before any memory is set aside for it.
constexpr std::size_t kShortestFieldLine = 6;
constexpr int kMaxTokensKept = 8;
// How long an input that is not a regular file (a FIFO, a pipe, a terminal) may keep the reader
// waiting for a writer's first bytes, and then for each next block: a writer that has stopped
// sending is reported, not waited for forever. A slow writer that keeps sending is read.
constexpr int kInputWaitSeconds = 5;

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

// Where the reader's lines come from: a text in memory, or a file read a block at a time, so
// that reading stops at the first line that cannot belong to a world (a binary file, a device
// that never ends, a line with no end) instead of after the whole input.
class LineSource {
 public:
  explicit LineSource(std::string_view text) : memory_(text), remaining_(text.size()) {}
  // `size`: the file's size when it is a regular file, -1 when unknown (a pipe, a device).
  LineSource(int fd, long long size)
      : fd_(fd), sizeKnown_(size >= 0), remaining_(size >= 0 ? size : 0) {}

  enum class Status { Line, End, TooLong };
  // Thrown by next() when an input of unknown size sent nothing for kInputWaitSeconds.
  struct Stalled {};

  // The next line without its '\n', valid until the next call (for TooLong, its start).
  Status next(std::string_view* line) {
    if (fd_ < 0) {
      if (pos_ >= memory_.size()) return Status::End;
      std::size_t end = memory_.find('\n', pos_);
      if (end == std::string_view::npos) end = memory_.size();
      if (end - pos_ > kMaxLineLength) {  // as for a file: the same text, the same verdict
        *line = memory_.substr(pos_, kMaxLineLength);
        return Status::TooLong;
      }
      *line = memory_.substr(pos_, end - pos_);
      consumed(end + 1 - pos_);
      pos_ = end + 1;
      return Status::Line;
    }
    std::size_t searched = begin_;
    for (;;) {
      const char* start = buffer_.data() + searched;
      const void* newline = std::memchr(start, '\n', end_ - searched);
      if (newline) {
        std::size_t at = static_cast<const char*>(newline) - buffer_.data();
        if (at - begin_ > kMaxLineLength) {  // a long line that arrived whole within one block
          *line = std::string_view(buffer_.data() + begin_, kMaxLineLength);
          return Status::TooLong;
        }
        *line = std::string_view(buffer_.data() + begin_, at - begin_);
        consumed(at + 1 - begin_);
        begin_ = at + 1;
        return Status::Line;
      }
      if (end_ - begin_ > kMaxLineLength) {
        *line = std::string_view(buffer_.data() + begin_,
                                 kMaxLineLength);  // the start, for the message
        return Status::TooLong;
      }
      if (eof_) {
        if (begin_ == end_) return Status::End;
        *line = std::string_view(buffer_.data() + begin_, end_ - begin_);
        consumed(end_ - begin_);
        begin_ = end_;
        return Status::Line;
      }
      // Keep the partial line, read more after it.
      std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
      end_ -= begin_;
      begin_ = 0;
      searched = end_;
      if (buffer_.size() - end_ < kBlock) buffer_.resize(end_ + kBlock);
      if (!sizeKnown_) waitForData();
      ssize_t got;
      do got = ::read(fd_, buffer_.data() + end_, kBlock);
      while (got < 0 && errno == EINTR);
      if (got < 0) throw std::system_error(errno, std::generic_category(), "cannot read");
      if (got == 0) eof_ = true;
      end_ += static_cast<std::size_t>(got);
    }
  }

  // Bytes not yet consumed, when the input's size is known.
  bool remainingKnown() const { return fd_ < 0 || sizeKnown_; }
  std::size_t remainingBytes() const { return remaining_; }

  static constexpr std::size_t kMaxLineLength = 4096;  // far beyond any record of a world

 private:
  static constexpr std::size_t kBlock = 1 << 16;
  void consumed(std::size_t bytes) { remaining_ -= std::min(remaining_, bytes); }

  // Waits until read() will not block (data, end of input or an error to report).
  void waitForData() {
    pollfd waiting{fd_, POLLIN, 0};
    int ready;
    do ready = ::poll(&waiting, 1, kInputWaitSeconds * 1000);
    while (ready < 0 && errno == EINTR);
    if (ready == 0) throw Stalled{};
  }

  std::string_view memory_;
  std::size_t pos_ = 0;
  int fd_ = -1;
  bool sizeKnown_ = false;
  std::string buffer_;
  std::size_t begin_ = 0, end_ = 0;
  bool eof_ = false;
  std::size_t remaining_ = 0;
};

class Parser {
 public:
  Parser(LineSource& source, const std::string& name) : source_(source), name_(name) {}

  [[noreturn]] void fail(int line, const std::string& what, const std::string& field) const {
    throw WorldFileError(name_ + ":" + std::to_string(line) + ": " + what + " (" + field + ")");
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

void appendNumber(std::string& out, double value) {
  char buffer[32];
  auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

void appendLine(std::string& out, std::initializer_list<double> values) {
  bool first = true;
  for (double value : values) {
    if (!first) out += ' ';
    appendNumber(out, value);
    first = false;
  }
  out += '\n';
}

}  // namespace

std::string latticeLabel(int q) {
  const int perSlab = kLatticeSize * kLatticeSize;
  return "[" + std::to_string(q / perSlab) + "][" +
         std::to_string((q / kLatticeSize) % kLatticeSize) + "][" +
         std::to_string(q % kLatticeSize) + "]";
}

namespace {
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

// The size of the blocks formatWorldInBlocks hands out, bytes: large enough that writing them
// costs few system calls, small beside any field worth streaming.
constexpr std::size_t kFormatBlock = 1 << 16;

// Doubles set aside at first for a field whose input has no known size (a pipe): the vector
// then grows with what actually arrives, not with what the resolution line claims.
constexpr std::size_t kUnknownSizeReserve = 3 << 16;

void readIntegrator(Parser& in, World& w) {
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

// dt n, the springs' four constants, and the mass.
void readParameters(Parser& in, World& w) {
  in.record(2, "dt n");
  w.dt = in.positive(0, "dt");
  w.n = in.integer(1, "n");
  if (w.n < 1) in.fail(in.line(), "must be >= 1, got " + Parser::str(in.token(1)), "n");

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
    if (w.plane.a == 0 && w.plane.b == 0 && w.plane.c == 0) {
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

WorldFile parseLines(LineSource& source, const std::string& name) {
  Parser in(source, name);
  WorldFile result;
  readIntegrator(in, result.world);
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

}  // namespace

namespace {

std::string triple(const double* v, const char* unit) {
  char text[96];
  std::snprintf(text, sizeof text, "(%g, %g, %g) %s", v[0], v[1], v[2], unit);
  return text;
}

bool finite3(const double* v) {
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

// The parameters' rules, as parseLines applies them to a file's tokens.
std::optional<WorldProblem> findParameterProblem(const World& w) {
  using Part = WorldProblem::Part;
  auto problem = [](Part part, const std::string& what) { return WorldProblem{part, 0, what}; };
  auto number = [](double value) {
    std::string text;
    appendNumber(text, value);
    return text;
  };
  if (!(std::isfinite(w.dt) && w.dt > 0))
    return problem(Part::Parameters, "dt must be > 0 and finite, got " + number(w.dt));
  if (w.n < 1) return problem(Part::Parameters, "n must be >= 1, got " + std::to_string(w.n));
  const std::pair<const char*, double> nonNegative[] = {{"kElastic", w.kElastic},
                                                        {"dElastic", w.dElastic},
                                                        {"kCollision", w.kCollision},
                                                        {"dCollision", w.dCollision}};
  for (auto [name, value] : nonNegative) {
    if (!(std::isfinite(value) && value >= 0))
      return problem(Part::Parameters,
                     std::string(name) + " must be >= 0 and finite, got " + number(value));
  }
  if (!(std::isfinite(w.mass) && w.mass > 0))
    return problem(Part::Parameters, "mass must be > 0 and finite, got " + number(w.mass));
  if (w.hasPlane) {
    const double plane[4] = {w.plane.a, w.plane.b, w.plane.c, w.plane.d};
    if (!finite3(plane) || !std::isfinite(plane[3]))
      return problem(Part::Plane, "the plane's coefficients must be finite");
    if (plane[0] == 0 && plane[1] == 0 && plane[2] == 0)
      return problem(Part::Plane, "the plane's normal (a,b,c) is zero");
  }
  return std::nullopt;
}

}  // namespace

std::optional<WorldProblem> findWorldProblem(const World& w, const State& state) {
  using Part = WorldProblem::Part;
  if (auto problem = findParameterProblem(w)) return problem;
  const int r = w.field.resolution;
  const std::size_t nodes = r > 0 ? static_cast<std::size_t>(r) * r * r : 0;
  if (r < 0 || r > kMaxResolution || w.field.forces.size() != 3 * nodes) {
    return WorldProblem{Part::Field, 0,
                        "the field's resolution " + std::to_string(r) + " does not match its " +
                            std::to_string(w.field.forces.size()) + " values"};
  }
  for (std::size_t n = 0; n < nodes; ++n) {
    const double* force = &w.field.forces[3 * n];
    if (finite3(force)) continue;
    const std::size_t i = n / (static_cast<std::size_t>(r) * r), j = (n / r) % r, k = n % r;
    return WorldProblem{Part::Field, n,
                        "the force at field node (" + std::to_string(i) + "," + std::to_string(j) +
                            "," + std::to_string(k) + ") is " + triple(force, "N") +
                            ", not finite"};
  }
  const std::pair<const double*, Part> arrays[] = {{state.p(), Part::Position},
                                                   {state.v(), Part::Velocity}};
  const int n = state.points();
  JELLO_ASSERT(n == bodyOf(w).count());
  for (auto [points, part] : arrays) {
    for (int q = 0; q < n; ++q) {
      const Vec3 a = load(points, q, n);
      const double value[3] = {a.x, a.y, a.z};
      if (finite3(value)) continue;
      const bool position = part == Part::Position;
      return WorldProblem{part, static_cast<std::size_t>(q),
                          std::string(position ? "the position" : "the velocity") + " of point " +
                              bodyOf(w).label(q) + " is " + triple(value, position ? "m" : "m/s") +
                              ", not finite"};
    }
  }
  return std::nullopt;
}

WorldFile parseWorld(std::string_view text, const std::string& name) {
  LineSource source(text);
  return parseLines(source, name);
}

WorldFile readWorldFile(const std::string& path) {
  // Non-blocking open: a FIFO nobody writes to must not hang the reader; reads themselves
  // block as usual, after a wait of at most kInputWaitSeconds for data (LineSource).
  int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) throw WorldFileError(path + ": cannot open: " + std::strerror(errno));
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat info {};
  if (::fstat(fd, &info) != 0)
    throw WorldFileError(path + ": cannot read: " + std::strerror(errno));
  if (S_ISDIR(info.st_mode)) throw WorldFileError(path + ": is a directory, not a world file");
  if (S_ISFIFO(info.st_mode)) {
    // Wait for a writer's first bytes (or its hanging up) as cat would, but not forever.
    pollfd waiting{fd, POLLIN, 0};
    int ready;
    do ready = ::poll(&waiting, 1, kInputWaitSeconds * 1000);
    while (ready < 0 && errno == EINTR);
    if (ready == 0) {
      throw WorldFileError(path + ": a FIFO nothing was written to within " +
                           std::to_string(kInputWaitSeconds) + " s");
    }
  }
  int flags = ::fcntl(fd, F_GETFL);
  if (flags >= 0) ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
  LineSource source(fd, S_ISREG(info.st_mode) ? static_cast<long long>(info.st_size) : -1);
  try {
    return parseLines(source, path);
  } catch (const std::system_error& e) {
    throw WorldFileError(path + ": " + e.what());
  }
}

void formatWorldInBlocks(const World& w, const State& state,
                         const std::function<void(std::string_view)>& write) {
  std::string out;
  out.reserve(kFormatBlock + 256);
  auto flushFull = [&] {
    if (out.size() < kFormatBlock) return;
    write(out);
    out.clear();
  };
  out += integratorName(w.integrator);
  out += '\n';
  appendNumber(out, w.dt);
  out += ' ' + std::to_string(w.n) + '\n';
  appendLine(out, {w.kElastic, w.dElastic, w.kCollision, w.dCollision});
  appendLine(out, {w.mass});
  out += w.hasPlane ? "1\n" : "0\n";
  if (w.hasPlane) appendLine(out, {w.plane.a, w.plane.b, w.plane.c, w.plane.d});
  out += std::to_string(w.field.resolution) + '\n';
  const std::vector<double>& f = w.field.forces;
  for (std::size_t i = 0; i + 2 < f.size(); i += 3) {
    appendLine(out, {f[i], f[i + 1], f[i + 2]});
    flushFull();
  }
  for (const double* points : {state.p(), state.v()}) {
    for (int q = 0; q < kNumPoints; ++q) {
      Vec3 a = load(points, q);
      appendLine(out, {a.x, a.y, a.z});
      flushFull();
    }
  }
  if (!out.empty()) write(out);
}

std::string formatWorld(const World& w, const State& state) {
  std::string out;
  formatWorldInBlocks(w, state, [&](std::string_view block) { out += block; });
  return out;
}

void writeWorldFile(const std::string& path, const World& world, const State& state,
                    bool overwrite) {
  // The text goes out a block at a time: a large field's text is never held whole.
  writeFileWhole(
      path,
      [&](std::FILE* file) {
        formatWorldInBlocks(world, state, [file](std::string_view block) {
          if (std::fwrite(block.data(), 1, block.size(), file) != block.size())
            throw std::runtime_error(std::string("cannot write: ") + std::strerror(errno));
        });
      },
      overwrite ? Existing::Replace : Existing::Refuse);
}

}  // namespace jello
