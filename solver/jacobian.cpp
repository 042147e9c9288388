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

// The pattern of `blocks` as a sparse matrix of zeros, in either storage order.
template <class Matrix>
Matrix patternMatrix(const std::vector<std::pair<int, int>>& blocks) {
  std::vector<Eigen::Triplet<double>> entries;
  for (auto [row, column] : blocks)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        entries.emplace_back(coordIndex(row, i), coordIndex(column, j), 0.0);
  Matrix pattern(kNumCoords, kNumCoords);
  pattern.setFromTriplets(entries.begin(), entries.end());
  pattern.makeCompressed();
  return pattern;
}

// Where every block's entries, and every diagonal entry, are in `pattern`'s value array.
template <class Matrix>
void findSlots(const std::vector<std::pair<int, int>>& blocks, const Matrix& pattern,
               std::vector<BlockSlots>* blockSlots, std::vector<int>* diagonal) {
  const int* outer = pattern.outerIndexPtr();
  const int* inner = pattern.innerIndexPtr();
  auto find = [&](int row, int column) {
    const int major = Matrix::IsRowMajor ? row : column, minor = Matrix::IsRowMajor ? column : row;
    const int* at = std::lower_bound(inner + outer[major], inner + outer[major + 1], minor);
    return static_cast<int>(at - inner);
  };
  blockSlots->clear();
  for (auto [row, column] : blocks) {
    BlockSlots slots;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        slots[3 * i + j] = find(coordIndex(row, i), coordIndex(column, j));
    blockSlots->push_back(slots);
  }
  diagonal->resize(kNumCoords);
  for (int i = 0; i < kNumCoords; ++i) (*diagonal)[i] = find(i, i);
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

// Pair blocks go straight into the matrices (their slots in order); point blocks are summed
// over the terms first, then written once, as the point's whole force would be. `Write` puts a
// block's derivatives by position and by velocity, times a sign, at the block's slots:
// write(slots, dFdp, dFdv, sign).
template <class Write>
class Assembly final : public JacobianSink {
 public:
  Assembly(const std::vector<BlockSlots>& slots, std::vector<Block3>* pointP,
           std::vector<Block3>* pointV, Write write)
      : slots_(slots), pointP_(*pointP), pointV_(*pointV), write_(write) {
    pointP_.assign(kNumPoints, Block3{});
    pointV_.assign(kNumPoints, Block3{});
  }
  void addPair(const Block3& dFdL, const Block3& dFdw) override {
    JELLO_ASSERT(slot_ + 4 + kNumPoints <= slots_.size());
    for (double sign : {1.0, -1.0, -1.0, 1.0})  // aa, ab, ba, bb
      write_(slots_[slot_++], dFdL, dFdw, sign);
  }
  void addPoint(int q, const Block3& dFdp, const Block3& dFdv) override {
    accumulate(&pointP_[q], dFdp);
    accumulate(&pointV_[q], dFdv);
  }
  // The diagonal blocks, with the user's pull (a spring to a fixed target: -stiffness I).
  void finish(const Pull* pull) {
    // Every pair term gave as many pairs as it listed when the pattern was built.
    JELLO_ASSERT(slot_ + kNumPoints == slots_.size());
    for (int q = 0; q < kNumPoints; ++q, ++slot_) {
      Block3& blockP = pointP_[q];
      if (pull && pull->point == q)
        for (int axis = 0; axis < 3; ++axis) blockP.m[4 * axis] -= pull->stiffness;
      write_(slots_[slot_], blockP, pointV_[q], 1.0);
    }
  }

 private:
  const std::vector<BlockSlots>& slots_;
  std::vector<Block3>&pointP_, &pointV_;
  Write write_;
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

template <class Write>
void assemble(const Model& model, const double* p, const double* v, const Pull* pull,
              const std::vector<BlockSlots>& slots, std::vector<Block3>* pointP,
              std::vector<Block3>* pointV, Write write) {
  Assembly<Write> assembly(slots, pointP, pointV, write);
  for (const auto& term : model.scene.terms) term->addJacobian(p, v, &assembly);
  assembly.finish(pull);
}

}  // namespace

void accelerationJacobian(const Model& model, const double* p, const double* v, const Pull* pull,
                          AccelerationJacobian* out) {
  // The pattern is made once per model shape; later calls only check that it still fits.
  if (out->blockSlots.size() != patternBlockCount(model)) {
    const std::vector<std::pair<int, int>> blocks = patternBlocks(model);
    out->dAdp = patternMatrix<SparseMatrix>(blocks);
    out->dAdv = out->dAdp;
    findSlots(blocks, out->dAdp, &out->blockSlots, &out->diagonal);
  }
  double* dp = out->dAdp.valuePtr();
  double* dv = out->dAdv.valuePtr();
  std::fill(dp, dp + out->dAdp.nonZeros(), 0.0);
  std::fill(dv, dv + out->dAdv.nonZeros(), 0.0);
  const double perMass = 1.0 / model.world.mass;
  assemble(model, p, v, pull, out->blockSlots, &out->pointP, &out->pointV,
           [dp, dv, perMass](const BlockSlots& slots, const Block3& dFdp, const Block3& dFdv,
                             double sign) {
             addBlock(dp, slots, dFdp, sign * perMass);
             addBlock(dv, slots, dFdv, sign * perMass);
           });
  if (!model.pinned.empty()) zeroPinnedRows(model.pinned, out);
}

namespace {

// Block B of each pair, as the terms give them, and the point terms' blocks summed per point.
class BlockAssembly final : public JacobianSink {
 public:
  BlockAssembly(NewtonBlocks* out, double byPosition, double byVelocity)
      : out_(*out), byPosition_(byPosition), byVelocity_(byVelocity) {
    out_.pointP.assign(kNumPoints, Block3{});
    out_.pointV.assign(kNumPoints, Block3{});
  }
  void addPair(const Block3& dFdL, const Block3& dFdw) override {
    JELLO_ASSERT(pair_ < out_.pair.size());
    Block3& b = out_.pair[pair_++];
    for (int e = 0; e < 9; ++e) b.m[e] = byPosition_ * dFdL.m[e] + byVelocity_ * dFdw.m[e];
  }
  void addPoint(int q, const Block3& dFdp, const Block3& dFdv) override {
    accumulate(&out_.pointP[q], dFdp);
    accumulate(&out_.pointV[q], dFdv);
  }
  // The diagonal blocks: the identity, the point terms and the user's pull (-stiffness I).
  void finish(const Pull* pull) {
    JELLO_ASSERT(pair_ == out_.pair.size());
    for (int q = 0; q < kNumPoints; ++q) {
      Block3& blockP = out_.pointP[q];
      if (pull && pull->point == q)
        for (int axis = 0; axis < 3; ++axis) blockP.m[4 * axis] -= pull->stiffness;
      Block3& b = out_.point[q];
      for (int e = 0; e < 9; ++e)
        b.m[e] = byPosition_ * blockP.m[e] + byVelocity_ * out_.pointV[q].m[e];
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
  std::vector<char> isPinned(kNumPoints, 0);
  for (int q : blocks.pinned) isPinned[q] = 1;
  std::vector<Eigen::Triplet<double>> entries;
  auto add = [&](int row, int column, const Block3& b, double sign) {
    if (isPinned[row]) return;
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
