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

std::vector<char> pinnedCoordinates(const std::vector<int>& pinned) {
  std::vector<char> isPinned(kNumCoords, 0);
  for (int q : pinned)
    for (int axis = 0; axis < 3; ++axis) isPinned[coordIndex(q, axis)] = 1;
  return isPinned;
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

// The pattern of `blocks` as a sparse matrix of zeros.
SparseMatrix patternMatrix(const std::vector<std::pair<int, int>>& blocks) {
  std::vector<Eigen::Triplet<double>> entries;
  for (auto [row, column] : blocks)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        entries.emplace_back(coordIndex(row, i), coordIndex(column, j), 0.0);
  SparseMatrix pattern(kNumCoords, kNumCoords);
  pattern.setFromTriplets(entries.begin(), entries.end());
  pattern.makeCompressed();
  return pattern;
}

// Where every block's entries are in `pattern`'s value array (column-major).
std::vector<BlockSlots> findSlots(const std::vector<std::pair<int, int>>& blocks,
                                  const SparseMatrix& pattern) {
  const int* outer = pattern.outerIndexPtr();
  const int* inner = pattern.innerIndexPtr();
  auto find = [&](int row, int column) {
    const int* at = std::lower_bound(inner + outer[column], inner + outer[column + 1], row);
    return static_cast<int>(at - inner);
  };
  std::vector<BlockSlots> slots;
  for (auto [row, column] : blocks) {
    BlockSlots block;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        block[3 * i + j] = find(coordIndex(row, i), coordIndex(column, j));
    slots.push_back(block);
  }
  return slots;
}

void addBlock(double* values, const BlockSlots& slots, const Block3& block, double scale) {
  for (int e = 0; e < 9; ++e) values[slots[e]] += scale * block.m[e];
}

void accumulate(Block3* sum, const Block3& block) {
  for (int e = 0; e < 9; ++e) sum->m[e] += block.m[e];
}

// How many blocks the model's pattern has: a matrix whose slots list as many fits it.
std::size_t patternBlockCount(const Model& model) {
  std::size_t blocks = kNumPoints;
  for (const auto& term : model.scene.terms) blocks += 4 * term->pairCount();
  return blocks;
}

// What both assemblies share: the point terms' blocks are summed per point over the terms
// (into the caller's scratch), then taken once per point with the user's pull added (a spring to
// a fixed target: -stiffness I), as the point's whole force is.
class PointSums : public JacobianSink {
 public:
  PointSums(std::vector<Block3>* pointP, std::vector<Block3>* pointV)
      : pointP_(*pointP), pointV_(*pointV) {
    pointP_.assign(kNumPoints, Block3{});
    pointV_.assign(kNumPoints, Block3{});
  }
  void addPoint(int q, const Block3& dFdp, const Block3& dFdv) override {
    accumulate(&pointP_[q], dFdp);
    accumulate(&pointV_[q], dFdv);
  }

 protected:
  // Point q's blocks by position (the pull included) and by velocity; once per point.
  const Block3& byPosition(int q, const Pull* pull) {
    if (pull && pull->point == q)
      for (int axis = 0; axis < 3; ++axis) pointP_[q].m[4 * axis] -= pull->stiffness;
    return pointP_[q];
  }
  const Block3& byVelocity(int q) const { return pointV_[q]; }

 private:
  std::vector<Block3>&pointP_, &pointV_;
};

// dA/dp and dA/dv as sparse matrices: pair blocks go straight in (their slots in order), then
// the points' blocks, scaled by 1/mass.
class Assembly final : public PointSums {
 public:
  Assembly(AccelerationJacobian* out, double perMass)
      : PointSums(&out->pointP, &out->pointV), out_(*out), perMass_(perMass) {}
  void addPair(const Block3& dFdL, const Block3& dFdw) override {
    JELLO_ASSERT(slot_ + 4 + kNumPoints <= out_.blockSlots.size());
    for (double sign : {1.0, -1.0, -1.0, 1.0}) {  // aa, ab, ba, bb
      addBlock(out_.dAdp.valuePtr(), out_.blockSlots[slot_], dFdL, sign * perMass_);
      addBlock(out_.dAdv.valuePtr(), out_.blockSlots[slot_], dFdw, sign * perMass_);
      ++slot_;
    }
  }
  void finish(const Pull* pull) {
    // Every pair term gave as many pairs as it listed when the pattern was built.
    JELLO_ASSERT(slot_ + kNumPoints == out_.blockSlots.size());
    for (int q = 0; q < kNumPoints; ++q, ++slot_) {
      addBlock(out_.dAdp.valuePtr(), out_.blockSlots[slot_], byPosition(q, pull), perMass_);
      addBlock(out_.dAdv.valuePtr(), out_.blockSlots[slot_], byVelocity(q), perMass_);
    }
  }

 private:
  AccelerationJacobian& out_;
  double perMass_;
  std::size_t slot_ = 0;
};

// A pinned point's acceleration is 0 whatever the state (physics.cpp's derivative): its rows are
// zero. (IMPLICIT's Newton step then leaves its velocity at 0.)
void zeroPinnedRows(const std::vector<int>& pinned, AccelerationJacobian* out) {
  const std::vector<char> isPinned = pinnedCoordinates(pinned);
  for (SparseMatrix* m : {&out->dAdp, &out->dAdv})
    for (Eigen::Index e = 0; e < m->nonZeros(); ++e)
      if (isPinned[m->innerIndexPtr()[e]]) m->valuePtr()[e] = 0;
}

}  // namespace

void accelerationJacobian(const Model& model, const double* p, const double* v, const Pull* pull,
                          AccelerationJacobian* out) {
  // The pattern is made once per model shape; later calls only check that it still fits.
  if (out->blockSlots.size() != patternBlockCount(model)) {
    const std::vector<std::pair<int, int>> blocks = patternBlocks(model);
    out->dAdp = patternMatrix(blocks);
    out->dAdv = out->dAdp;
    out->blockSlots = findSlots(blocks, out->dAdp);
  }
  std::fill(out->dAdp.valuePtr(), out->dAdp.valuePtr() + out->dAdp.nonZeros(), 0.0);
  std::fill(out->dAdv.valuePtr(), out->dAdv.valuePtr() + out->dAdv.nonZeros(), 0.0);
  Assembly assembly(out, 1.0 / model.world.mass);
  for (const auto& term : model.scene.terms) term->addJacobian(p, v, &assembly);
  assembly.finish(pull);
  if (!model.pinned.empty()) zeroPinnedRows(model.pinned, out);
}

namespace {

// Block B of each pair, as the terms give them, and each point's diagonal block.
class BlockAssembly final : public PointSums {
 public:
  BlockAssembly(NewtonBlocks* out, double byPosition, double byVelocity)
      : PointSums(&out->pointP, &out->pointV),
        out_(*out),
        byPosition_(byPosition),
        byVelocity_(byVelocity) {}
  void addPair(const Block3& dFdL, const Block3& dFdw) override {
    JELLO_ASSERT(pair_ < out_.pair.size());
    Block3& b = out_.pair[pair_++];
    for (int e = 0; e < 9; ++e) b.m[e] = byPosition_ * dFdL.m[e] + byVelocity_ * dFdw.m[e];
  }
  // The diagonal blocks: the identity and the point terms' (the pull's included).
  void finish(const Pull* pull) {
    JELLO_ASSERT(pair_ == out_.pair.size());
    for (int q = 0; q < kNumPoints; ++q) {
      const Block3 &p = byPosition(q, pull), &v = byVelocity(q);
      Block3& b = out_.point[q];
      for (int e = 0; e < 9; ++e) b.m[e] = byPosition_ * p.m[e] + byVelocity_ * v.m[e];
      for (int axis = 0; axis < 3; ++axis) b.m[4 * axis] += 1;
    }
  }

 private:
  NewtonBlocks& out_;
  double byPosition_, byVelocity_;
  std::size_t pair_ = 0;
};

Vec3 times(const Block3& b, Vec3 x) {
  return {b.m[0] * x.x + b.m[1] * x.y + b.m[2] * x.z, b.m[3] * x.x + b.m[4] * x.y + b.m[5] * x.z,
          b.m[6] * x.x + b.m[7] * x.y + b.m[8] * x.z};
}

}  // namespace

void NewtonBlocks::multiply(const double* x, double* y) const {
  for (int q = 0; q < kNumPoints; ++q) store(y, q, times(point[q], load(x, q)));
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const auto [a, b] = pairs[k];
    const Vec3 f = times(pair[k], load(x, a) - load(x, b));
    store(y, a, load(y, a) + f);
    store(y, b, load(y, b) - f);
  }
  for (int q : pinned) store(y, q, load(x, q));
}

void NewtonBlocks::diagonal(double* d) const {
  for (int q = 0; q < kNumPoints; ++q)
    for (int axis = 0; axis < 3; ++axis) d[coordIndex(q, axis)] = point[q].m[4 * axis];
  for (std::size_t k = 0; k < pairs.size(); ++k)
    for (int axis = 0; axis < 3; ++axis) {
      d[coordIndex(pairs[k].first, axis)] += pair[k].m[4 * axis];
      d[coordIndex(pairs[k].second, axis)] += pair[k].m[4 * axis];
    }
  for (int q : pinned) store(d, q, Vec3{1, 1, 1});
}

void newtonBlocks(const Model& model, const double* p, const double* v, const Pull* pull, double cv,
                  double cp, NewtonBlocks* out) {
  // The pairs are listed once per model shape; later calls only check that they still fit.
  if (4 * out->pairs.size() + kNumPoints != patternBlockCount(model)) {
    out->pairs.clear();
    for (const auto& term : model.scene.terms)
      for (auto pair : term->pairs()) out->pairs.push_back(pair);
    out->pair.resize(out->pairs.size());
    out->point.resize(kNumPoints);
  }
  // -cp dA/dp - cv dA/dv, dA = dF / mass.
  BlockAssembly assembly(out, -cp / model.world.mass, -cv / model.world.mass);
  for (const auto& term : model.scene.terms) term->addJacobian(p, v, &assembly);
  assembly.finish(pull);
  out->pinned = model.pinned;
}

SparseMatrix sparseOf(const NewtonBlocks& blocks) {
  const std::vector<char> isPinned = pinnedCoordinates(blocks.pinned);
  std::vector<Eigen::Triplet<double>> entries;
  auto add = [&](int row, int column, const Block3& b, double sign) {
    if (isPinned[coordIndex(row, 0)]) return;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        entries.emplace_back(coordIndex(row, i), coordIndex(column, j), sign * b.m[3 * i + j]);
  };
  for (int q = 0; q < kNumPoints; ++q) add(q, q, blocks.point[q], 1);
  for (int q : blocks.pinned)
    for (int axis = 0; axis < 3; ++axis)
      entries.emplace_back(coordIndex(q, axis), coordIndex(q, axis), 1.0);
  for (std::size_t k = 0; k < blocks.pairs.size(); ++k) {
    const auto [a, b] = blocks.pairs[k];
    add(a, a, blocks.pair[k], 1);
    add(a, b, blocks.pair[k], -1);
    add(b, a, blocks.pair[k], -1);
    add(b, b, blocks.pair[k], 1);
  }
  SparseMatrix matrix(kNumCoords, kNumCoords);
  matrix.setFromTriplets(entries.begin(), entries.end());
  return matrix;
}

}  // namespace jello
