// jacobian.cpp: the terms' Jacobian blocks assembled as sparse matrices.

#include "solver/jacobian.h"

#include <algorithm>
#include <numeric>
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

std::vector<char> pinnedCoordinates(const std::vector<int>& pinned, int n) {
  std::vector<char> isPinned(3 * n, 0);
  for (int q : pinned)
    for (int axis = 0; axis < 3; ++axis) isPinned[coordIndex(q, axis, n)] = 1;
  return isPinned;
}

namespace {

// Every pair of the model's pair terms at positions p, in the terms' order: the pairs of its
// Jacobian blocks.
std::vector<std::pair<int, int>> pairsOf(const Model& model, const double* p) {
  std::vector<std::pair<int, int>> pairs;
  for (const auto& term : model.forces.terms) {
    const std::vector<std::pair<int, int>> own = term->pairsAt(p);
    pairs.insert(pairs.end(), own.begin(), own.end());
  }
  return pairs;
}

// Every block of the model's coupling terms (finite elements), in the terms' order.
std::vector<std::pair<int, int>> couplingsOf(const Model& model) {
  std::vector<std::pair<int, int>> blocks;
  for (const auto& term : model.forces.terms) {
    const std::vector<std::pair<int, int>> own = term->couplings();
    blocks.insert(blocks.end(), own.begin(), own.end());
  }
  return blocks;
}

std::size_t couplingCountOf(const Model& model) {
  std::size_t count = 0;
  for (const auto& term : model.forces.terms) count += term->couplingCount();
  return count;
}

// Whether `cached` (pairsOf at some positions) is the model's pairs at p: the terms whose pairs
// are fixed are checked by their count alone, those whose pairs move pair by pair.
bool samePairs(const Model& model, const double* p,
               const std::vector<std::pair<int, int>>& cached) {
  std::size_t at = 0;
  for (const auto& term : model.forces.terms) {
    if (!term->pairsMove()) {
      at += term->pairCount();
      continue;
    }
    for (const auto& pair : term->pairsAt(p))
      if (at >= cached.size() || cached[at++] != pair) return false;
  }
  return at == cached.size();
}

// Every (row, column) block of the pattern, in the order of AccelerationJacobian::blockSlots.
std::vector<std::pair<int, int>> patternBlocks(const std::vector<std::pair<int, int>>& pairs,
                                               const std::vector<std::pair<int, int>>& couplings,
                                               int points) {
  std::vector<std::pair<int, int>> blocks;
  blocks.reserve(4 * pairs.size() + couplings.size() + points);
  for (auto [a, b] : pairs)
    for (auto [row, column] : {std::pair{a, a}, {a, b}, {b, a}, {b, b}})
      blocks.push_back({row, column});
  blocks.insert(blocks.end(), couplings.begin(), couplings.end());
  for (int q = 0; q < points; ++q) blocks.push_back({q, q});
  return blocks;
}

// 1 / each point's mass.
std::vector<double> perMassOf(const Model& model) {
  std::vector<double> perMass(model.points());
  for (int q = 0; q < model.points(); ++q) perMass[q] = 1.0 / model.pointMass[q];
  return perMass;
}

// The pattern of `blocks` as a sparse matrix of zeros, its columns' row indices written out in
// order: through triplets, a 32^3 lattice's 15 million entries (most of them repeats of a point's
// own block) took seconds of copying and page faults.
SparseMatrix patternMatrix(std::vector<std::pair<int, int>> blocks, int n) {
  // By column point, then row point, each block once.
  for (auto& block : blocks) std::swap(block.first, block.second);
  std::sort(blocks.begin(), blocks.end());
  blocks.erase(std::unique(blocks.begin(), blocks.end()), blocks.end());
  std::vector<std::size_t> first(n + 1, 0);  // column point c's blocks: [first[c], first[c + 1])
  for (auto [column, row] : blocks) ++first[column + 1];
  std::partial_sum(first.begin(), first.end(), first.begin());
  SparseMatrix pattern(3 * n, 3 * n);
  pattern.resizeNonZeros(static_cast<Eigen::Index>(9 * blocks.size()));
  int* const outer = pattern.outerIndexPtr();
  outer[0] = 0;
  for (int c = 0; c < n; ++c)
    for (int j = 0; j < 3; ++j)
      outer[coordIndex(c, j, n) + 1] = static_cast<int>(3 * (first[c + 1] - first[c]));
  std::partial_sum(outer, outer + 3 * n + 1, outer);
  for (int c = 0; c < n; ++c)
    for (int j = 0; j < 3; ++j) {
      int* const begin = pattern.innerIndexPtr() + outer[coordIndex(c, j, n)];
      int* at = begin;
      for (std::size_t b = first[c]; b < first[c + 1]; ++b)
        for (int i = 0; i < 3; ++i) *at++ = coordIndex(blocks[b].second, i, n);
      std::sort(begin, at);
    }
  std::fill(pattern.valuePtr(), pattern.valuePtr() + pattern.nonZeros(), 0.0);
  return pattern;
}

// Where every block's entries are in `pattern`'s value array (column-major).
std::vector<BlockSlots> findSlots(const std::vector<std::pair<int, int>>& blocks,
                                  const SparseMatrix& pattern, int n) {
  const int* outer = pattern.outerIndexPtr();
  const int* inner = pattern.innerIndexPtr();
  auto find = [&](int row, int column) {
    const int* at = std::lower_bound(inner + outer[column], inner + outer[column + 1], row);
    return static_cast<int>(at - inner);
  };
  std::vector<BlockSlots> slots;
  slots.reserve(blocks.size());
  for (auto [row, column] : blocks) {
    BlockSlots block;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        block[3 * i + j] = find(coordIndex(row, i, n), coordIndex(column, j, n));
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

// What both assemblies share: the point terms' blocks are summed per point over the terms
// (into the caller's scratch), then taken once per point with the user's pull added (a spring to
// a fixed target: -stiffness I), as the point's whole force is.
class PointSums : public JacobianSink {
 public:
  PointSums(int points, std::vector<Block3>* pointP, std::vector<Block3>* pointV)
      : pointP_(*pointP), pointV_(*pointV) {
    pointP_.assign(points, Block3{});
    pointV_.assign(points, Block3{});
  }
  int points() const { return static_cast<int>(pointP_.size()); }
  void addPoint(int q, const Block3& dFdp, const Block3& dFdv) override {
    accumulate(&pointP_[q], dFdp);
    accumulate(&pointV_[q], dFdv);
  }
  // The place of the next term's first coupling block among all the terms'.
  void startTerm(std::size_t couplingOffset) { couplingOffset_ = couplingOffset; }

 protected:
  std::size_t couplingOffset_ = 0;

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
// the points' blocks, each row scaled by 1 / its point's mass.
class Assembly final : public PointSums {
 public:
  Assembly(int points, AccelerationJacobian* out, std::vector<double> perMass)
      : PointSums(points, &out->pointP, &out->pointV), out_(*out), perMass_(std::move(perMass)) {}
  void addPair(const Block3& dFdL, const Block3& dFdw) override {
    JELLO_ASSERT(slot_ + 4 + points() <= out_.blockSlots.size());
    JELLO_ASSERT(slot_ / 4 < out_.pairs.size());
    const auto [a, b] = out_.pairs[slot_ / 4];
    const double scale[4] = {perMass_[a], -perMass_[a], -perMass_[b], perMass_[b]};  // aa ab ba bb
    for (double sign : scale) {
      addBlock(out_.dAdp.valuePtr(), out_.blockSlots[slot_], dFdL, sign);
      addBlock(out_.dAdv.valuePtr(), out_.blockSlots[slot_], dFdw, sign);
      ++slot_;
    }
  }
  void addCoupling(std::size_t k, const Block3& dFdp, const Block3& dFdv) override {
    const std::size_t block = 4 * out_.pairs.size() + couplingOffset_ + k;
    JELLO_ASSERT(couplingOffset_ + k < out_.couplings);
    const int row = patternRow(block);
    addBlock(out_.dAdp.valuePtr(), out_.blockSlots[block], dFdp, perMass_[row]);
    addBlock(out_.dAdv.valuePtr(), out_.blockSlots[block], dFdv, perMass_[row]);
  }
  void finish(const Pull* pull) {
    // Every pair term gave as many pairs as it listed when the pattern was built.
    JELLO_ASSERT(slot_ == 4 * out_.pairs.size());
    slot_ += out_.couplings;
    JELLO_ASSERT(slot_ + points() == out_.blockSlots.size());
    for (int q = 0; q < points(); ++q, ++slot_) {
      addBlock(out_.dAdp.valuePtr(), out_.blockSlots[slot_], byPosition(q, pull), perMass_[q]);
      addBlock(out_.dAdv.valuePtr(), out_.blockSlots[slot_], byVelocity(q), perMass_[q]);
    }
  }

 private:
  // The row point of pattern block `block` (a coupling's).
  int patternRow(std::size_t block) const {
    return out_.couplingRows[block - 4 * out_.pairs.size()];
  }

  AccelerationJacobian& out_;
  std::vector<double> perMass_;
  std::size_t slot_ = 0;
};

// A pinned point's acceleration is 0 whatever the state (physics.cpp's derivative): its rows are
// zero. (IMPLICIT's Newton step then leaves its velocity at 0.)
void zeroPinnedRows(const std::vector<int>& pinned, int n, AccelerationJacobian* out) {
  const std::vector<char> isPinned = pinnedCoordinates(pinned, n);
  for (SparseMatrix* m : {&out->dAdp, &out->dAdv})
    for (Eigen::Index e = 0; e < m->nonZeros(); ++e)
      if (isPinned[m->innerIndexPtr()[e]]) m->valuePtr()[e] = 0;
}

}  // namespace

void accelerationJacobian(const Model& model, const double* p, const double* v, const Pull* pull,
                          AccelerationJacobian* out) {
  // The pattern is made once per model shape and pairs in contact; later calls only check that
  // it still fits.
  if (out->blockSlots.size() != 4 * out->pairs.size() + out->couplings + model.points() ||
      out->couplings != couplingCountOf(model) || !samePairs(model, p, out->pairs)) {
    out->pairs = pairsOf(model, p);
    const std::vector<std::pair<int, int>> couplings = couplingsOf(model);
    out->couplings = couplings.size();
    out->couplingRows.clear();
    for (auto [row, column] : couplings) out->couplingRows.push_back(row);
    const std::vector<std::pair<int, int>> blocks =
        patternBlocks(out->pairs, couplings, model.points());
    out->dAdp = patternMatrix(blocks, model.points());
    out->dAdv = out->dAdp;
    out->blockSlots = findSlots(blocks, out->dAdp, model.points());
  }
  std::fill(out->dAdp.valuePtr(), out->dAdp.valuePtr() + out->dAdp.nonZeros(), 0.0);
  std::fill(out->dAdv.valuePtr(), out->dAdv.valuePtr() + out->dAdv.nonZeros(), 0.0);
  Assembly assembly(model.points(), out, perMassOf(model));
  std::size_t offset = 0;
  for (const auto& term : model.forces.terms) {
    assembly.startTerm(offset);
    term->addJacobian(p, v, &assembly);
    offset += term->couplingCount();
  }
  assembly.finish(pull);
  if (!model.pinned.empty()) zeroPinnedRows(model.pinned, model.points(), out);
}

namespace {

// Block B of each pair, as the terms give them, and each point's diagonal block. With one mass
// for every point B is -cp dF/dL / m - cv dF/dw / m, the same for the pair's four blocks up to
// sign; with several, B is in force units and each row's 1 / mass is NewtonBlocks::rowScale's.
class BlockAssembly final : public PointSums {
 public:
  BlockAssembly(const Model& model, NewtonBlocks* out, double cv, double cp)
      : PointSums(model.points(), &out->pointP, &out->pointV), out_(*out), cv_(cv), cp_(cp) {
    const std::vector<double>& mass = model.pointMass;
    const bool uniform =
        std::all_of(mass.begin(), mass.end(), [&](double m) { return m == mass[0]; });
    mass_ = mass;
    out_.rowScale.clear();
    if (uniform) {
      const double common = mass.empty() ? model.world.mass : mass[0];
      byPosition_ = -cp / common;
      byVelocity_ = -cv / common;
    } else {
      byPosition_ = -cp;
      byVelocity_ = -cv;
      for (double m : mass) out_.rowScale.push_back(1.0 / m);
    }
  }
  void addPair(const Block3& dFdL, const Block3& dFdw) override {
    JELLO_ASSERT(pair_ < out_.pair.size());
    Block3& b = out_.pair[pair_++];
    for (int e = 0; e < 9; ++e) b.m[e] = byPosition_ * dFdL.m[e] + byVelocity_ * dFdw.m[e];
  }
  void addCoupling(std::size_t k, const Block3& dFdp, const Block3& dFdv) override {
    JELLO_ASSERT(couplingOffset_ + k < out_.coupling.size());
    Block3& b = out_.coupling[couplingOffset_ + k];
    for (int e = 0; e < 9; ++e) b.m[e] += byPosition_ * dFdp.m[e] + byVelocity_ * dFdv.m[e];
  }
  // The diagonal blocks: the identity and the point terms' (the pull's included).
  void finish(const Pull* pull) {
    JELLO_ASSERT(pair_ == out_.pair.size());
    const bool uniform = out_.rowScale.empty();
    for (int q = 0; q < points(); ++q) {
      const Block3 &p = byPosition(q, pull), &v = byVelocity(q);
      const double byP = uniform ? byPosition_ : -cp_ / mass_[q];
      const double byV = uniform ? byVelocity_ : -cv_ / mass_[q];
      Block3& b = out_.point[q];
      for (int e = 0; e < 9; ++e) b.m[e] = byP * p.m[e] + byV * v.m[e];
      for (int axis = 0; axis < 3; ++axis) b.m[4 * axis] += 1;
    }
  }

 private:
  NewtonBlocks& out_;
  double cv_, cp_;
  std::vector<double> mass_;
  double byPosition_ = 0, byVelocity_ = 0;
  std::size_t pair_ = 0;
};

Vec3 times(const Block3& b, Vec3 x) {
  return {b.m[0] * x.x + b.m[1] * x.y + b.m[2] * x.z, b.m[3] * x.x + b.m[4] * x.y + b.m[5] * x.z,
          b.m[6] * x.x + b.m[7] * x.y + b.m[8] * x.z};
}

}  // namespace

void NewtonBlocks::multiply(const double* x, double* y) const {
  const int n = points();
  for (int q = 0; q < n; ++q) store(y, q, n, times(point[q], load(x, q, n)));
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const auto [a, b] = pairs[k];
    const Vec3 f = times(pair[k], load(x, a, n) - load(x, b, n));
    if (rowScale.empty()) {
      store(y, a, n, load(y, a, n) + f);
      store(y, b, n, load(y, b, n) - f);
    } else {
      store(y, a, n, load(y, a, n) + rowScale[a] * f);
      store(y, b, n, load(y, b, n) - rowScale[b] * f);
    }
  }
  for (std::size_t k = 0; k < couplings.size(); ++k) {
    const auto [row, column] = couplings[k];
    const Vec3 f = times(coupling[k], load(x, column, n));
    store(y, row, n, load(y, row, n) + (rowScale.empty() ? f : rowScale[row] * f));
  }
  for (int q : pinned) store(y, q, n, load(x, q, n));
}

void NewtonBlocks::diagonal(double* d) const {
  const int n = points();
  for (int q = 0; q < n; ++q)
    for (int axis = 0; axis < 3; ++axis) d[coordIndex(q, axis, n)] = point[q].m[4 * axis];
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const auto [a, b] = pairs[k];
    const double scaleA = rowScale.empty() ? 1.0 : rowScale[a];
    const double scaleB = rowScale.empty() ? 1.0 : rowScale[b];
    for (int axis = 0; axis < 3; ++axis) {
      d[coordIndex(a, axis, n)] += scaleA * pair[k].m[4 * axis];
      d[coordIndex(b, axis, n)] += scaleB * pair[k].m[4 * axis];
    }
  }
  for (std::size_t k = 0; k < couplings.size(); ++k) {
    const auto [row, column] = couplings[k];
    if (row != column) continue;
    const double scale = rowScale.empty() ? 1.0 : rowScale[row];
    for (int axis = 0; axis < 3; ++axis)
      d[coordIndex(row, axis, n)] += scale * coupling[k].m[4 * axis];
  }
  for (int q : pinned) store(d, q, n, Vec3{1, 1, 1});
}

void newtonBlocks(const Model& model, const double* p, const double* v, const Pull* pull, double cv,
                  double cp, NewtonBlocks* out) {
  // The pairs are listed once per model shape and pairs in contact; later calls only check that
  // they still fit.
  if (out->points() != model.points() || !samePairs(model, p, out->pairs)) {
    out->pairs = pairsOf(model, p);
    out->pair.resize(out->pairs.size());
    out->point.resize(model.points());
  }
  if (out->coupling.size() != couplingCountOf(model)) {
    out->couplings = couplingsOf(model);
    out->coupling.resize(out->couplings.size());
  }
  std::fill(out->coupling.begin(), out->coupling.end(), Block3{});
  // -cp dA/dp - cv dA/dv, dA = dF / mass.
  BlockAssembly assembly(model, out, cv, cp);
  std::size_t offset = 0;
  for (const auto& term : model.forces.terms) {
    assembly.startTerm(offset);
    term->addJacobian(p, v, &assembly);
    offset += term->couplingCount();
  }
  assembly.finish(pull);
  out->pinned = model.pinned;
}

SparseMatrix sparseOf(const NewtonBlocks& blocks) {
  const int n = blocks.points();
  const std::vector<char> isPinned = pinnedCoordinates(blocks.pinned, n);
  std::vector<Eigen::Triplet<double>> entries;
  auto add = [&](int row, int column, const Block3& b, double sign) {
    if (isPinned[coordIndex(row, 0, n)]) return;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        entries.emplace_back(coordIndex(row, i, n), coordIndex(column, j, n),
                             sign * b.m[3 * i + j]);
  };
  for (int q = 0; q < n; ++q) add(q, q, blocks.point[q], 1);
  for (int q : blocks.pinned)
    for (int axis = 0; axis < 3; ++axis)
      entries.emplace_back(coordIndex(q, axis, n), coordIndex(q, axis, n), 1.0);
  for (std::size_t k = 0; k < blocks.pairs.size(); ++k) {
    const auto [a, b] = blocks.pairs[k];
    const double scaleA = blocks.rowScale.empty() ? 1.0 : blocks.rowScale[a];
    const double scaleB = blocks.rowScale.empty() ? 1.0 : blocks.rowScale[b];
    add(a, a, blocks.pair[k], scaleA);
    add(a, b, blocks.pair[k], -scaleA);
    add(b, a, blocks.pair[k], -scaleB);
    add(b, b, blocks.pair[k], scaleB);
  }
  for (std::size_t k = 0; k < blocks.couplings.size(); ++k) {
    const auto [row, column] = blocks.couplings[k];
    add(row, column, blocks.coupling[k], blocks.rowScale.empty() ? 1.0 : blocks.rowScale[row]);
  }
  SparseMatrix matrix(3 * n, 3 * n);
  matrix.setFromTriplets(entries.begin(), entries.end());
  return matrix;
}

}  // namespace jello
