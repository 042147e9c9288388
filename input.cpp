// input.cpp (the course's file): reading and writing world files (io/input.h,
// docs/world-format.md). The line parser is io/worldparser.cpp, the rules on values
// io/worldcheck.cpp; here are the file's opening (a FIFO waited for, never forever) and the
// round-trip writer.

#include "io/input.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstring>
#include <functional>
#include <string>
#include <system_error>

#include "core/assert.h"
#include "core/output.h"
#include "io/worldparser.h"
#include "model/model.h"

namespace jello {

namespace {

// The size of the blocks formatWorldInBlocks hands out, bytes: large enough that writing them
// costs few system calls, small beside any field worth streaming.
constexpr std::size_t kFormatBlock = 1 << 16;

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

void appendNumber(std::string& out, double value) {
  char buffer[32];
  auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

WorldFile parseWorld(std::string_view text, const std::string& name) {
  LineSource source(text);
  return parseLines(source, name);
}

WorldFile readWorldFile(const std::string& path) {
  // Non-blocking open: a FIFO nobody writes to must not hang the reader; reads themselves
  // block as usual, after a wait of at most kInputWaitSeconds for data (LineSource).
  int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) throw InputError(path + ": cannot open: " + std::strerror(errno));
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat info {};
  if (::fstat(fd, &info) != 0) throw InputError(path + ": cannot read: " + std::strerror(errno));
  if (S_ISDIR(info.st_mode)) throw InputError(path + ": is a directory, not a world file");
  if (S_ISFIFO(info.st_mode)) {
    // Wait for a writer's first bytes (or its hanging up) as cat would, but not forever.
    pollfd waiting{fd, POLLIN, 0};
    int ready;
    do ready = ::poll(&waiting, 1, kInputWaitSeconds * 1000);
    while (ready < 0 && errno == EINTR);
    if (ready == 0) {
      throw InputError(path + ": a FIFO nothing was written to within " +
                       std::to_string(kInputWaitSeconds) + " s");
    }
  }
  int flags = ::fcntl(fd, F_GETFL);
  if (flags >= 0) ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
  LineSource source(fd, S_ISREG(info.st_mode) ? static_cast<long long>(info.st_size) : -1);
  try {
    return parseLines(source, path);
  } catch (const std::system_error& e) {
    throw InputError(path + ": " + e.what());
  }
}

void formatWorldInBlocks(const World& w, const RunSettings& run, const State& state,
                         const std::function<void(std::string_view)>& write) {
  // A world file holds the course cube: 512 positions and 512 velocities.
  JELLO_ASSERT(state.points() == kNumPoints);
  std::string out;
  out.reserve(kFormatBlock + 256);
  auto flushFull = [&] {
    if (out.size() < kFormatBlock) return;
    write(out);
    out.clear();
  };
  out += integratorName(run.integrator);
  out += '\n';
  appendNumber(out, run.dt);
  out += ' ' + std::to_string(run.n) + '\n';
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

std::string formatWorld(const World& w, const RunSettings& run, const State& state) {
  std::string out;
  formatWorldInBlocks(w, run, state, [&](std::string_view block) { out += block; });
  return out;
}

void writeWorldFile(const std::string& path, const World& world, const RunSettings& run,
                    const State& state, bool overwrite) {
  // The text goes out a block at a time: a large field's text is never held whole.
  writeFileWhole(
      path,
      [&](std::FILE* file) {
        formatWorldInBlocks(world, run, state, [file](std::string_view block) {
          if (std::fwrite(block.data(), 1, block.size(), file) != block.size())
            throw std::runtime_error(std::string("cannot write: ") + std::strerror(errno));
        });
      },
      overwrite ? Existing::Replace : Existing::Refuse);
}

}  // namespace jello
