// memory.cpp: memory needs of worlds, and what the machine and the process's limits allow.

#include "core/memory.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

namespace jello {

namespace {

constexpr std::uint64_t kUnlimited = std::numeric_limits<std::uint64_t>::max();
constexpr std::uint64_t kFieldBytesPerNode = 3 * sizeof(double);  // a World's ForceField
// A Model holds its own copy of the World (24) and the trilinear kernel's padded copy of the
// field, 4 doubles a node (model/field.h: the field term's padded nodes).
constexpr std::uint64_t kModelBytesPerNode = kFieldBytesPerNode + 4 * sizeof(double);
// Everything else a program allocates once a world is read, whatever its field: the springs,
// the integrators' states, the stability analysis's dense 1536 x 1536 matrices (19 MB each).
// Measured as the smallest `ulimit -v` that lets each mode finish, less what the process holds
// at start (7 MB): a run 1-4 MB (IMPLICIT 15), createWorld 45, jello --check 95, --bench 110.
constexpr std::uint64_t kFixedBytes = 128ull << 20;

std::uint64_t g_limit = 0;
WorldUse g_use = WorldUse::Run;

std::uint64_t bytesPerNode(WorldUse use, bool streamed) {
  std::uint64_t held = kFieldBytesPerNode;
  if (use == WorldUse::Run) held += kModelBytesPerNode;
  if (use == WorldUse::Bench) held += 2 * kModelBytesPerNode + kFieldBytesPerNode;
  // Read from a pipe, the field's vector doubles (up to its announced size) as lines arrive:
  // while it moves, the old block and the new one are both held.
  const std::uint64_t reading = streamed ? 2 * kFieldBytesPerNode : kFieldBytesPerNode;
  return std::max(held, reading);
}

// The smallest of the memory limits of the cgroups holding this process, v2 (memory.max) or
// v1 (memory.limit_in_bytes), from its own group up to the root. kUnlimited when none is set
// or none can be read.
std::uint64_t cgroupLimit() {
  std::ifstream groups("/proc/self/cgroup");
  std::uint64_t limit = kUnlimited;
  for (std::string line; std::getline(groups, line);) {
    // "0::/path" (v2) or "4:memory:/path" (v1)
    std::size_t first = line.find(':'), second = line.find(':', first + 1);
    if (first == std::string::npos || second == std::string::npos) continue;
    std::string controllers = line.substr(first + 1, second - first - 1);
    std::string path = line.substr(second + 1);
    std::string root, file;
    if (controllers.empty()) {
      root = "/sys/fs/cgroup", file = "/memory.max";
    } else if (controllers == "memory") {
      root = "/sys/fs/cgroup/memory", file = "/memory.limit_in_bytes";
    } else {
      continue;
    }
    for (;;) {
      std::ifstream in(root + (path == "/" ? "" : path) + file);
      std::uint64_t value = 0;
      if (in >> value) limit = std::min(limit, value);  // "max" reads as no number: no limit
      if (path.empty() || path == "/") break;
      std::size_t slash = path.find_last_of('/');
      path = slash == 0 ? "/" : path.substr(0, slash);
    }
  }
  return limit;
}

// What `resource` leaves of its soft limit beyond `used` bytes.
std::uint64_t rlimitLeft(int resource, std::uint64_t used) {
  rlimit limit{};
  if (::getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return kUnlimited;
  return limit.rlim_cur > used ? limit.rlim_cur - used : 0;
}

}  // namespace

std::uint64_t worldMemoryNeed(int resolution, WorldUse use, bool streamed) {
  const std::uint64_t r = resolution > 0 ? static_cast<std::uint64_t>(resolution) : 0;
  return kFixedBytes + r * r * r * bytesPerNode(use, streamed);
}

void setWorldUse(WorldUse use) { g_use = use; }
WorldUse worldUse() { return g_use; }
void setMemoryLimit(std::uint64_t bytes) { g_limit = bytes; }

std::uint64_t availableMemory() {
  const std::uint64_t page = static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));
  std::uint64_t machine = g_limit;
  if (machine == 0) {
    long pages = ::sysconf(_SC_PHYS_PAGES);
    machine =
        std::min(pages > 0 ? static_cast<std::uint64_t>(pages) * page : kUnlimited, cgroupLimit());
  }
  // statm: sizes in pages; the first is the address space (RLIMIT_AS counts it), the sixth
  // data and stack (RLIMIT_DATA counts the private writable part of it).
  std::uint64_t addressSpace = 0, resident = 0, shared = 0, text = 0, library = 0, data = 0;
  std::ifstream statm("/proc/self/statm");
  statm >> addressSpace >> resident >> shared >> text >> library >> data;
  return std::min(
      {machine, rlimitLeft(RLIMIT_AS, addressSpace * page), rlimitLeft(RLIMIT_DATA, data * page)});
}

std::string notEnoughMemoryMessage(std::uint64_t needed, std::uint64_t available) {
  auto gigabytes = [](std::uint64_t bytes) {
    char text[32];
    const double value = static_cast<double>(bytes) / 1e9;
    std::snprintf(text, sizeof text, value >= 100 ? "%.0f GB" : "%.3g GB", value);
    return std::string(text);
  };
  return "not enough memory for this world: needs " + gigabytes(needed) + ", " +
         gigabytes(available) + " available";
}

void requireMemory(std::uint64_t bytes) {
  const std::uint64_t available = availableMemory();
  if (bytes > available) throw NotEnoughMemory(bytes, available);
}

}  // namespace jello
