// memory.h: the memory a world needs and the memory this process may use, so that a world too
// large for the machine is refused with one line before anything is allocated for it, instead
// of ending in std::bad_alloc (or the kernel's OOM killer) halfway through.
//
// Units: bytes. "GB" in messages and on command lines (--max-memory) is 10^9 bytes.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace jello {

// What a program does with a world, which fixes how many copies of its force field it holds at
// its peak (the field is all that grows with a world: R^3 nodes of 3 doubles, 24 bytes a node).
enum class WorldUse {
  Create,  // createWorld: the field once; written out in blocks, validated in place
  Run,     // jello: the world read, and its Model's copy of the World and padded field
  Bench,   // jello --bench: a run with two Models, reading the world again meanwhile
};

// Peak bytes a world of field resolution R (0 to kMaxResolution) needs under `use`, the
// program's own fixed needs included. `streamed`: the world is read from a pipe or device,
// whose size is not known beforehand, so the field grows in steps while it is read.
std::uint64_t worldMemoryNeed(int resolution, WorldUse use, bool streamed = false);

// What readWorldFile assumes its worlds are read for (default Run); set once by main.
void setWorldUse(WorldUse use);
WorldUse worldUse();

// --max-memory: the bytes this process may use, in place of the machine's physical memory and
// its cgroup's limit (e.g. to leave room for other work, or to count on swap). The process's
// own limits (ulimit -v, -d) still apply: an allocation beyond them fails whatever is said.
// 0: the machine's figures.
void setMemoryLimit(std::uint64_t bytes);

// Bytes this process may still allocate: the smaller of the physical memory (or the
// setMemoryLimit figure), the cgroup's memory limit when readable, and what RLIMIT_AS and
// RLIMIT_DATA leave beyond what the process already holds.
std::uint64_t availableMemory();

// "not enough memory for this world: needs 10.8 GB, 3.0 GB available"
std::string notEnoughMemoryMessage(std::uint64_t needed, std::uint64_t available);

// A world that does not fit. what() is notEnoughMemoryMessage.
class NotEnoughMemory : public std::runtime_error {
 public:
  NotEnoughMemory(std::uint64_t needed, std::uint64_t available)
      : std::runtime_error(notEnoughMemoryMessage(needed, available)),
        needed_(needed),
        available_(available) {}
  std::uint64_t needed() const { return needed_; }
  std::uint64_t available() const { return available_; }

 private:
  std::uint64_t needed_, available_;
};

// Throws NotEnoughMemory when `bytes` exceed availableMemory().
void requireMemory(std::uint64_t bytes);

}  // namespace jello
