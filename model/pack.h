// model/pack.h: eight doubles operated on together, the unit of work of the force kernels.
//
// A Pack is a lattice row's worth of doubles (kLatticeSize points along k): with AVX-512
// (-march=native on a processor that has it) one 512-bit register, with AVX two 256-bit ones,
// with SSE2 four 128-bit ones, each piece a GCC/clang vector of the register's width. (GCC keeps
// a vector wider than the registers in memory and compares it a lane at a time: that made the
// kernels 4 times slower with AVX2.) Its operators are the element-wise IEEE operations, each
// lane rounding exactly as the same scalar expression would: a kernel written with Packs gives
// the same bits as its loop over single points, whatever the instruction set.
#pragma once

#include <cstring>
#include <utility>

#include "model/world.h"

// Without AVX-512 a 512-bit vector handed to a function that is not inlined is passed differently
// than with it, and GCC and clang warn about it (-Wpsabi). Only the kernel files include this
// header, and every function of theirs that takes or returns vectors is internal to its file,
// built with one set of flags: the calling conventions of two builds never meet.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace jello {

constexpr int kPackLanes = 8;
static_assert(kPackLanes == kLatticeSize, "a lattice row is one pack");
static_assert(kNumPoints % kPackLanes == 0);

// The processor's vector registers, in doubles.
#if defined(__AVX512F__)
#define JELLO_PACK_ONE_REGISTER 1  // a Pack is one register: whole-Pack shuffles
constexpr int kNativeLanes = 8;
#elif defined(__AVX__)
constexpr int kNativeLanes = 4;
#else
constexpr int kNativeLanes = 2;
#endif
constexpr int kPackPieces = kPackLanes / kNativeLanes;
typedef double NativePack __attribute__((vector_size(kNativeLanes * sizeof(double))));

// Every function here is inlined into its kernel, but in the sanitizers' builds
// (JELLO_KERNEL_CALLS): there the compiler decides, as the instrumented kernels inlined whole took
// clang over ten minutes a file (model/springgrid.cpp, 2026-11-28).
#ifdef JELLO_KERNEL_CALLS
#define JELLO_PACK_INLINE inline
#else
#define JELLO_PACK_INLINE inline __attribute__((always_inline))
#endif

struct Pack {
  NativePack piece[kPackPieces] = {};
  double lane(int l) const { return piece[l / kNativeLanes][l % kNativeLanes]; }
  void setLane(int l, double x) { piece[l / kNativeLanes][l % kNativeLanes] = x; }
};

// f(piece of each pack...) for each register-wide piece, put back together: the element-wise
// operations, and the kernels' comparisons and selects, written on NativePacks.
template <class F, class... Packs>
JELLO_PACK_INLINE Pack byPiece(F f, const Packs&... packs) {
  Pack out;
  for (int c = 0; c < kPackPieces; ++c) out.piece[c] = f(packs.piece[c]...);
  return out;
}

JELLO_PACK_INLINE Pack operator+(const Pack& a, const Pack& b) {
  return byPiece([](NativePack x, NativePack y) { return x + y; }, a, b);
}
JELLO_PACK_INLINE Pack operator-(const Pack& a, const Pack& b) {
  return byPiece([](NativePack x, NativePack y) { return x - y; }, a, b);
}
JELLO_PACK_INLINE Pack operator*(const Pack& a, const Pack& b) {
  return byPiece([](NativePack x, NativePack y) { return x * y; }, a, b);
}
JELLO_PACK_INLINE Pack operator/(const Pack& a, const Pack& b) {
  return byPiece([](NativePack x, NativePack y) { return x / y; }, a, b);
}

JELLO_PACK_INLINE Pack splat(double x) {
  Pack out;
  for (NativePack& p : out.piece) p = NativePack{} + x;
  return out;
}
JELLO_PACK_INLINE Pack operator+(const Pack& a, double b) { return a + splat(b); }
JELLO_PACK_INLINE Pack operator-(const Pack& a, double b) { return a - splat(b); }
JELLO_PACK_INLINE Pack operator*(const Pack& a, double b) { return a * splat(b); }

// The 8 doubles at a (any alignment) and back.
JELLO_PACK_INLINE Pack loadPack(const double* a) {
  Pack out;
  for (int c = 0; c < kPackPieces; ++c)
    std::memcpy(&out.piece[c], a + c * kNativeLanes, sizeof(NativePack));
  return out;
}
JELLO_PACK_INLINE void storePack(double* a, const Pack& value) {
  for (int c = 0; c < kPackPieces; ++c)
    std::memcpy(a + c * kNativeLanes, &value.piece[c], sizeof(NativePack));
}

// Lane by lane; the compiler makes one vector square root (or floor) of each piece's loop.
JELLO_PACK_INLINE Pack sqrtPack(const Pack& x) {
  return byPiece(
      [](NativePack p) {
        for (int l = 0; l < kNativeLanes; ++l) p[l] = __builtin_sqrt(p[l]);
        return p;
      },
      x);
}
JELLO_PACK_INLINE Pack floorPack(const Pack& x) {
  return byPiece(
      [](NativePack p) {
        for (int l = 0; l < kNativeLanes; ++l) p[l] = __builtin_floor(p[l]);
        return p;
      },
      x);
}

namespace pack_detail {
template <int kFirst, std::size_t... kLane>
JELLO_PACK_INLINE NativePack piecesFrom(NativePack a, NativePack b, std::index_sequence<kLane...>) {
  if constexpr (kFirst == 0)
    return a;
  else
    return __builtin_shufflevector(a, b, (kFirst + static_cast<int>(kLane))...);
}
}  // namespace pack_detail

// The register's worth of lanes that starts kFirst lanes into a and runs on into b
// (0 <= kFirst < kNativeLanes).
template <int kFirst>
JELLO_PACK_INLINE NativePack nativeLanesFrom(NativePack a, NativePack b) {
  static_assert(kFirst >= 0 && kFirst < kNativeLanes);
  return pack_detail::piecesFrom<kFirst>(a, b, std::make_index_sequence<kNativeLanes>{});
}

namespace pack_detail {
template <int kFirst, std::size_t... kPiece>
JELLO_PACK_INLINE Pack lanesFrom(const Pack& lo, const Pack& hi, std::index_sequence<kPiece...>) {
  // Piece c of the result starts kFirst + c * kNativeLanes lanes into lo then hi.
  auto pieceOf = [&lo, &hi](int p) {
    return p < kPackPieces ? lo.piece[p] : hi.piece[p - kPackPieces];
  };
  Pack out;
  ((out.piece[kPiece] = nativeLanesFrom<kFirst % kNativeLanes>(
        pieceOf(kFirst / kNativeLanes + static_cast<int>(kPiece)),
        pieceOf(kFirst / kNativeLanes + static_cast<int>(kPiece) + 1))),
   ...);
  return out;
}
}  // namespace pack_detail

// The 8 lanes that start kFirst lanes into lo and run on into hi (0 <= kFirst < 8).
template <int kFirst>
JELLO_PACK_INLINE Pack lanesFrom(const Pack& lo, const Pack& hi) {
  static_assert(kFirst >= 0 && kFirst < kPackLanes);
  return pack_detail::lanesFrom<kFirst>(lo, hi, std::make_index_sequence<kPackPieces>{});
}

}  // namespace jello
