// jacobian.cpp: the terms' Jacobian blocks assembled as sparse matrices.

#include "solver/jacobian.h"

#include <algorithm>
#include <utility>
#include <vector>

#include "core/assert.h"

namespace jello {

Mat3 toMatrix(const Block3& block) {
  Mat3 m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m(i, j) = block.m[3 * i + j];
  return m;
}

namespace {

// Every (row, column) block of the pattern, in the order of AccelerationJacobian::blockSlots.
std::vector<std::pair<int, int>> patternBlocks(const Model& model) {
  std::vector<std::pair<int, int>> blocks;
  for (const auto& term : model.scene.terms)
    for (auto [a, b] : term->pairs())
      for (auto [row, column] : {std::pair{a, a}, {a, b}, {b, a}, {b, b}})
        blocks.push_back({row, column});
  for (int q = 0; q < kNumPoints; ++q) blocks.push_back({q, q});
  return blocks;
}

// The shared pattern and the index of every block in it.
void buildPattern(const std::vector<std::pair<int, int>>& blocks, AccelerationJacobian* out) {
  std::vector<Eigen::Triplet<double>> entries;
  for (auto [row, column] : blocks)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        entries.emplace_back(coordIndex(row, i), coordIndex(column, j), 0.0);
  SparseMatrix pattern(kNumCoords, kNumCoords);
  pattern.setFromTriplets(entries.begin(), entries.end());
  pattern.makeCompressed();
  out->dAdp = pattern;
  out->dAdv = pattern;
  const int* outer = pattern.outerIndexPtr();
  const int* inner = pattern.innerIndexPtr();
  auto find = [&](int row, int column) {
    const int* at = std::lower_bound(inner + outer[column], inner + outer[column + 1], row);
    return static_cast<int>(at - inner);
  };
  out->blockSlots.clear();
  for (auto [row, column] : blocks) {
    BlockSlots slots;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        slots[3 * i + j] = find(coordIndex(row, i), coordIndex(column, j));
    out->blockSlots.push_back(slots);
  }
  out->diagonal.resize(kNumCoords);
  for (int i = 0; i < kNumCoords; ++i) out->diagonal[i] = find(i, i);
}

void addBlock(double* values, const BlockSlots& slots, const Block3& block, double scale) {
  for (int e = 0; e < 9; ++e) values[slots[e]] += scale * block.m[e];
}

void accumulate(Block3* sum, const Block3& block) {
  for (int e = 0; e < 9; ++e) sum->m[e] += block.m[e];
}

// Pair blocks go straight into the matrices (their slots in order); point blocks are summed
// over the terms first, then scaled once, as the point's whole force would be.
class Assembly final : public JacobianSink {
 public:
  Assembly(AccelerationJacobian* out, double perMass) : out_(out), perMass_(perMass) {}
  void addPair(const Block3& dFdL, const Block3& dFdw) override {
    JELLO_ASSERT(slot_ + 4 + kNumPoints <= out_->blockSlots.size());
    for (double sign : {1.0, -1.0, -1.0, 1.0}) {  // aa, ab, ba, bb
      addBlock(out_->dAdp.valuePtr(), out_->blockSlots[slot_], dFdL, sign * perMass_);
      addBlock(out_->dAdv.valuePtr(), out_->blockSlots[slot_], dFdw, sign * perMass_);
      ++slot_;
    }
  }
  void addPoint(int q, const Block3& dFdp, const Block3& dFdv) override {
    accumulate(&out_->pointP[q], dFdp);
    accumulate(&out_->pointV[q], dFdv);
  }
  // The diagonal blocks, with the user's pull (a spring to a fixed target: -stiffness I).
  void finish(const Pull* pull) {
    // Every pair term gave as many pairs as it listed when the pattern was built.
    JELLO_ASSERT(slot_ + kNumPoints == out_->blockSlots.size());
    for (int q = 0; q < kNumPoints; ++q, ++slot_) {
      Block3& blockP = out_->pointP[q];
      if (pull && pull->point == q)
        for (int axis = 0; axis < 3; ++axis) blockP.m[4 * axis] -= pull->stiffness;
      addBlock(out_->dAdp.valuePtr(), out_->blockSlots[slot_], blockP, perMass_);
      addBlock(out_->dAdv.valuePtr(), out_->blockSlots[slot_], out_->pointV[q], perMass_);
    }
  }

 private:
  AccelerationJacobian* out_;
  double perMass_;
  std::size_t slot_ = 0;
};

// A pinned point's acceleration is 0 whatever the state (physics.cpp's derivative): its rows are
// zero. (IMPLICIT's Newton step then leaves its velocity at 0.)
void zeroPinnedRows(const std::vector<int>& pinned, AccelerationJacobian* out) {
  std::vector<char> isPinned(kNumCoords, 0);
  for (int q : pinned)
    for (int axis = 0; axis < 3; ++axis) isPinned[coordIndex(q, axis)] = 1;
  for (SparseMatrix* m : {&out->dAdp, &out->dAdv})
    for (Eigen::Index e = 0; e < m->nonZeros(); ++e)
      if (isPinned[m->innerIndexPtr()[e]]) m->valuePtr()[e] = 0;
}

}  // namespace

void accelerationJacobian(const Model& model, const double* p, const double* v, const Pull* pull,
                          AccelerationJacobian* out) {
  // The pattern is made once per model shape; later calls only check that it still fits.
  std::size_t blocks = kNumPoints;
  for (const auto& term : model.scene.terms) blocks += 4 * term->pairCount();
  if (out->blockSlots.size() != blocks) buildPattern(patternBlocks(model), out);
  std::fill(out->dAdp.valuePtr(), out->dAdp.valuePtr() + out->dAdp.nonZeros(), 0.0);
  std::fill(out->dAdv.valuePtr(), out->dAdv.valuePtr() + out->dAdv.nonZeros(), 0.0);
  out->pointP.assign(kNumPoints, Block3{});
  out->pointV.assign(kNumPoints, Block3{});
  Assembly assembly(out, 1.0 / model.world.mass);
  for (const auto& term : model.scene.terms) term->addJacobian(p, v, &assembly);
  assembly.finish(pull);
  if (!model.pinned.empty()) zeroPinnedRows(model.pinned, out);
}

}  // namespace jello
