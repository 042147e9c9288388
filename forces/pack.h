// forces/pack.h: eight doubles operated on together, the unit of work of the force kernels.
//
// A Pack is a GCC/clang vector of 8 doubles: one 512-bit register where the force sources are
// built for a processor with AVX-512 (-march=native), two or four narrower ones elsewhere. Its
// operators are the element-wise IEEE operations, each lane rounding exactly as the same scalar
// expression would: a kernel written with Packs gives the same bits as its loop over single
// points, whatever the instruction set. Eight lanes is a lattice row (kLatticeSize points along
// k), so a row of the structure-of-arrays positions is one Pack.
#pragma once

#include "world.h"

// Without AVX-512 a Pack handed to a function that is not inlined is passed differently than with
// it, and GCC and clang warn about it (-Wpsabi). Only the kernel files include this header, and
// every function of theirs that takes or returns Packs is internal to its file, built with one
// set of flags: the calling conventions of two builds never meet.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace jello {

constexpr int kPackLanes = 8;
static_assert(kPackLanes == kLatticeSize, "a lattice row is one pack");
static_assert(kNumPoints % kPackLanes == 0);

typedef double Pack __attribute__((vector_size(kPackLanes * sizeof(double))));
// Lane-wise comparisons give 0 or -1 (all bits set) per lane, as 64-bit integers; a comparison
// can select between Packs: (a < b ? x : y).
typedef long long PackIndex __attribute__((vector_size(kPackLanes * sizeof(long long))));

// Every function here is inlined into its kernel: none is ever called with a Pack argument, so
// the calling convention for vector arguments (which AVX-512 changes) never applies.
#define JELLO_PACK_INLINE inline __attribute__((always_inline))

// The 8 doubles at a (any alignment) and back.
JELLO_PACK_INLINE Pack loadPack(const double* a) {
  Pack out;
  __builtin_memcpy(&out, a, sizeof out);
  return out;
}
JELLO_PACK_INLINE void storePack(double* a, Pack value) {
  __builtin_memcpy(a, &value, sizeof value);
}

JELLO_PACK_INLINE Pack splat(double x) { return Pack{} + x; }

// Lane by lane; the compiler makes one vector square root (or floor) of the loop.
JELLO_PACK_INLINE Pack sqrtPack(Pack x) {
  Pack out;
  for (int l = 0; l < kPackLanes; ++l) out[l] = __builtin_sqrt(x[l]);
  return out;
}
JELLO_PACK_INLINE Pack floorPack(Pack x) {
  Pack out;
  for (int l = 0; l < kPackLanes; ++l) out[l] = __builtin_floor(x[l]);
  return out;
}

}  // namespace jello
