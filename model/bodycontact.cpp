// model/bodycontact.cpp: contact between bodies and of a body with itself (bodycontact.h).

#include "model/bodycontact.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "core/assert.h"

namespace jello {

namespace {

// A cell coordinate, clamped so that three fit in a 63-bit key (a point that far is diverged; the
// step's check catches it).
constexpr std::int64_t kCellReach = std::int64_t(1) << 20;
std::int64_t cellCoordinate(double x, double cell) {
  const double c = std::floor(x / cell);
  if (!(c > -double(kCellReach))) return 0;  // also NaN
  if (!(c < double(kCellReach - 2))) return 2 * kCellReach - 2;
  return static_cast<std::int64_t>(c) + kCellReach;
}
std::int64_t cellKey(std::int64_t x, std::int64_t y, std::int64_t z) {
  return (x << 42) | (y << 21) | z;
}

}  // namespace

BodyContactTerm::BodyContactTerm(const Body& body, std::vector<ContactPart> parts,
                                 const BodyContactSpec& spec)
    : ForceTerm(body.count()), parts_(std::move(parts)) {
  JELLO_ASSERT(parts_.size() == (body.joined() ? body.parts.size() : 1u));
  law_.shape = ObstacleShape::Sphere;
  law_.spring = spec.spring;
  law_.friction = spec.friction;
  const int n = body.count();
  partOf_.resize(n);
  gridOf_.resize(n);
  radiusOf_.resize(n);
  for (int q = 0; q < n; ++q) {
    partOf_[q] = body.partOf(q);
    gridOf_[q] = body.index(q);
    radiusOf_[q] = parts_[partOf_[q]].radius;
    JELLO_ASSERT(radiusOf_[q] > 0);
  }
  // A part takes part when there is another, or when it touches itself.
  for (int q : body.surfacePoints)
    if (parts_.size() > 1 || parts_[partOf_[q]].selfContact) candidates_.push_back(q);
  for (const ContactPart& part : parts_) cell_ = std::max(cell_, 2 * part.radius);
}

bool BodyContactTerm::mayTouch(int a, int b) const {
  if (partOf_[a] != partOf_[b]) return true;
  if (!parts_[partOf_[a]].selfContact) return false;
  for (int axis = 0; axis < 3; ++axis)
    if (std::abs(gridOf_[a][axis] - gridOf_[b][axis]) > kSelfNeighbourhood) return true;
  return false;
}

void BodyContactTerm::activeCandidates(const double* p, std::vector<Bounds>* boxes,
                                       std::vector<int>* active) const {
  // Each part's box about its surface points; a point of a part without self-contact may touch
  // only where another part's box, grown by the cell edge, reaches it.
  const int n = pointCount();
  std::vector<Bounds>& box = *boxes;
  box.assign(parts_.size(),
             Bounds{{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}});
  for (int q : candidates_) {
    const Vec3 x = load(p, q, n);
    Bounds& b = box[partOf_[q]];
    b.lower = {std::min(b.lower.x, x.x), std::min(b.lower.y, x.y), std::min(b.lower.z, x.z)};
    b.upper = {std::max(b.upper.x, x.x), std::max(b.upper.y, x.y), std::max(b.upper.z, x.z)};
  }
  active->clear();
  for (int q : candidates_) {
    const int part = partOf_[q];
    bool near = parts_[part].selfContact;
    const Vec3 x = load(p, q, n);
    for (std::size_t other = 0; other < parts_.size() && !near; ++other) {
      if (int(other) == part) continue;
      const Bounds& b = box[other];
      near = x.x >= b.lower.x - cell_ && x.x <= b.upper.x + cell_ && x.y >= b.lower.y - cell_ &&
             x.y <= b.upper.y + cell_ && x.z >= b.lower.z - cell_ && x.z <= b.upper.z + cell_;
    }
    // A point that is not finite goes in too: the step's check reports the divergence.
    if (near || !std::isfinite(x.x + x.y + x.z)) active->push_back(q);
  }
}

namespace {

// The occupied cells of the broad phase's grid: each cell's run of candidates in the sorted list.
// Where the candidates' cells span a box of at most kDenseCellsPerRun cells a run (bodies near each
// other), a dense array over that box finds a cell's run in one read; otherwise an open-addressing
// table (a power of two, at most half full) by the cell's key.
constexpr std::size_t kDenseCellsPerRun = 64;

class CellTable {
 public:
  struct Run {
    std::int64_t key;
    int begin, end;  // in the sorted list
  };
  // Made again for these keys (sorted) and cells; the buffers are kept (no allocation once they
  // are large enough).
  void rebuild(const std::vector<std::int64_t>& sortedKeys,
               const std::vector<std::array<std::int64_t, 3>>& cells) {
    runs_.clear();
    dense_.clear();
    slots_.clear();
    shift_ = 60;
    for (int i = 0; i < static_cast<int>(sortedKeys.size()); ++i)
      if (runs_.empty() || runs_.back().key != sortedKeys[i])
        runs_.push_back({sortedKeys[i], i, i + 1});
      else
        runs_.back().end = i + 1;
    if (cells.empty()) return;
    low_ = high_ = cells[0];
    for (const auto& c : cells)
      for (int axis = 0; axis < 3; ++axis)
        low_[axis] = std::min(low_[axis], c[axis]), high_[axis] = std::max(high_[axis], c[axis]);
    for (int axis = 0; axis < 3; ++axis) span_[axis] = high_[axis] - low_[axis] + 1;
    const double volume = double(span_[0]) * double(span_[1]) * double(span_[2]);
    if (volume <= double(kDenseCellsPerRun * runs_.size() + 4096)) {
      dense_.assign(static_cast<std::size_t>(volume), -1);
      for (int r = 0; r < static_cast<int>(runs_.size()); ++r) dense_[denseIndex(runs_[r].key)] = r;
      return;
    }
    std::size_t size = 16;
    while (size < 2 * runs_.size()) size *= 2, --shift_;
    slots_.assign(size, -1);
    mask_ = size - 1;
    for (int r = 0; r < static_cast<int>(runs_.size()); ++r) {
      std::size_t at = hash(runs_[r].key);
      while (slots_[at] >= 0) at = (at + 1) & mask_;
      slots_[at] = r;
    }
  }
  // The run of cell (x, y, z), or null when no candidate is in it.
  const Run* find(std::int64_t x, std::int64_t y, std::int64_t z) const {
    if (!dense_.empty()) {
      if (x < low_[0] || y < low_[1] || z < low_[2] || x > high_[0] || y > high_[1] || z > high_[2])
        return nullptr;
      const int r = dense_[static_cast<std::size_t>(
          ((x - low_[0]) * span_[1] + (y - low_[1])) * span_[2] + (z - low_[2]))];
      return r < 0 ? nullptr : &runs_[r];
    }
    if (slots_.empty()) return nullptr;
    const std::int64_t key = cellKey(x, y, z);
    for (std::size_t at = hash(key);; at = (at + 1) & mask_) {
      if (slots_[at] < 0) return nullptr;
      if (runs_[slots_[at]].key == key) return &runs_[slots_[at]];
    }
  }

 private:
  std::size_t denseIndex(std::int64_t key) const {
    const std::int64_t x = key >> 42, y = (key >> 21) & ((1 << 21) - 1), z = key & ((1 << 21) - 1);
    return static_cast<std::size_t>(((x - low_[0]) * span_[1] + (y - low_[1])) * span_[2] +
                                    (z - low_[2]));
  }
  // Fibonacci hashing: the top bits of the key times 2^64 / golden ratio.
  std::size_t hash(std::int64_t key) const {
    return static_cast<std::size_t>((static_cast<std::uint64_t>(key) * 0x9E3779B97F4A7C15ull) >>
                                    shift_);
  }
  std::vector<Run> runs_;
  std::array<std::int64_t, 3> low_{}, high_{}, span_{};
  std::vector<int> dense_, slots_;
  std::size_t mask_ = 0;
  int shift_ = 60;
};

}  // namespace

void BodyContactTerm::findContacts(const double* p, std::vector<ContactPair>* found) const {
  // This thread's buffers, kept from call to call: a step allocates nothing once they are grown.
  thread_local std::vector<Bounds> boxes;
  thread_local std::vector<int> active;
  thread_local std::vector<std::pair<std::int64_t, int>> sorted;
  thread_local std::vector<std::array<std::int64_t, 3>> cellOf;
  thread_local std::vector<std::int64_t> keys;
  thread_local CellTable cells;
  const int n = pointCount();
  activeCandidates(p, &boxes, &active);
  // The candidates by cell key, then point: (key, point) pairs sorted.
  sorted.clear();
  cellOf.resize(active.size());
  for (std::size_t i = 0; i < active.size(); ++i) {
    const Vec3 x = load(p, active[i], n);
    cellOf[i] = {cellCoordinate(x.x, cell_), cellCoordinate(x.y, cell_),
                 cellCoordinate(x.z, cell_)};
    sorted.emplace_back(cellKey(cellOf[i][0], cellOf[i][1], cellOf[i][2]), active[i]);
  }
  std::sort(sorted.begin(), sorted.end());
  keys.resize(sorted.size());
  for (std::size_t i = 0; i < sorted.size(); ++i) keys[i] = sorted[i].first;
  cells.rebuild(keys, cellOf);
  std::vector<ContactPair>& out = *found;
  out.clear();
  for (std::size_t i = 0; i < active.size(); ++i) {
    const int a = active[i];
    const Vec3 pa = load(p, a, n);
    int partners = 0;  // a's pairs so far, at most kMostContactPartners
    for (int cell = 0; cell < 27 && partners < kMostContactPartners; ++cell) {
      const int dx = cell / 9 - 1, dy = cell / 3 % 3 - 1, dz = cell % 3 - 1;
      const CellTable::Run* run =
          cells.find(cellOf[i][0] + dx, cellOf[i][1] + dy, cellOf[i][2] + dz);
      if (!run) continue;
      for (int at = run->begin; at < run->end && partners < kMostContactPartners; ++at) {
        const int b = sorted[at].second;
        if (b <= a || !mayTouch(a, b)) continue;
        const double distance = radiusOf_[a] + radiusOf_[b];
        const Vec3 L = pa - load(p, b, n);
        if (dot(L, L) < distance * distance) out.push_back({a, b, distance}), ++partners;
      }
    }
  }
  std::sort(out.begin(), out.end(), [](const ContactPair& x, const ContactPair& y) {
    return x.a < y.a || (x.a == y.a && x.b < y.b);
  });
}

std::vector<ContactPair> BodyContactTerm::contacts(const double* p) const {
  std::vector<ContactPair> out;
  findContacts(p, &out);
  return out;
}

const std::vector<ContactPair>& BodyContactTerm::contactsNow(const double* p) const {
  thread_local std::vector<ContactPair> pairs;
  findContacts(p, &pairs);
  return pairs;
}

Obstacle BodyContactTerm::ballOf(const ContactPair& pair) const {
  Obstacle ball = law_;
  ball.radius = pair.distance;
  return ball;
}

Vec3 BodyContactTerm::pairForce(const ContactPair& pair, Vec3 L, Vec3 w) const {
  return obstacleForce(ballOf(pair), L, w);
}

double BodyContactTerm::smallestGap(const double* p) const {
  const int n = pointCount();
  double smallest = INFINITY;
  if (parts_.size() < 2) return smallest;
  for (const ContactPair& pair : contactsNow(p))
    if (partOf_[pair.a] != partOf_[pair.b])
      smallest = std::min(smallest, length(load(p, pair.a, n) - load(p, pair.b, n)));
  return smallest;
}

std::vector<std::pair<int, int>> BodyContactTerm::pairsAt(const double* p) const {
  std::vector<std::pair<int, int>> out;
  for (const ContactPair& pair : contactsNow(p)) out.emplace_back(pair.a, pair.b);
  return out;
}

int BodyContactTerm::pointsInContact(const double* p) const {
  if (law_.spring.k == 0 && law_.spring.d == 0) return 0;
  std::vector<int> touching;
  for (const ContactPair& pair : contactsNow(p))
    touching.push_back(pair.a), touching.push_back(pair.b);
  std::sort(touching.begin(), touching.end());
  return static_cast<int>(std::unique(touching.begin(), touching.end()) - touching.begin());
}

void BodyContactTerm::addForcesOn(PointRange points, const double* p, const double* v,
                                  const Bounds*, double* force) const {
  // Each pair's force joins its ends in the pairs' order: a point's sum is the same whichever
  // range asks for it.
  const int n = pointCount();
  for (const ContactPair& pair : contactsNow(p)) {
    const bool aIn = pair.a >= points.begin && pair.a < points.end;
    const bool bIn = pair.b >= points.begin && pair.b < points.end;
    if (!aIn && !bIn) continue;
    const Vec3 f = pairForce(pair, load(p, pair.a, n) - load(p, pair.b, n),
                             load(v, pair.a, n) - load(v, pair.b, n));
    if (aIn) addAt(force, pair.a, f);
    if (bIn) store(force, pair.b, n, load(force, pair.b, n) - f);
  }
}

void BodyContactTerm::addJacobian(const double* p, const double* v, JacobianSink* sink) const {
  const int n = pointCount();
  Block3 dFdL, dFdw;
  for (const ContactPair& pair : contactsNow(p)) {
    obstacleJacobian(ballOf(pair), load(p, pair.a, n) - load(p, pair.b, n),
                     load(v, pair.a, n) - load(v, pair.b, n), &dFdL, &dFdw);
    sink->addPair(dFdL, dFdw);
  }
}

void BodyContactTerm::addEnergy(const double* p, double* energy) const {
  const int n = pointCount();
  for (const ContactPair& pair : contactsNow(p)) {
    const double depth = pair.distance - length(load(p, pair.a, n) - load(p, pair.b, n));
    *energy += 0.5 * law_.spring.k * depth * depth;
  }
}

void BodyContactTerm::summarise(std::vector<std::string>* kept, std::vector<std::string>*) const {
  bool self = false;
  for (const ContactPart& part : parts_) self = self || part.selfContact;
  std::string what = parts_.size() > 1 ? "contact between bodies" : "";
  if (self) what += std::string(what.empty() ? "" : " and ") + "self-contact";
  kept->push_back(what + (law_.friction.muStatic > 0 ? " with friction" : ""));
}

std::vector<TermLine> BodyContactTerm::describe(const double* p) const {
  std::string text = textf("k %.9g N/m, d %.9g N s/m, %zu surface points", law_.spring.k,
                           law_.spring.d, candidates_.size());
  if (law_.friction.muStatic > 0)
    text += textf(", friction mu_s %.6g, mu_d %.6g (eps %.3g m/s)", law_.friction.muStatic,
                  law_.friction.muDynamic, law_.friction.speed);
  text += textf(" (%d points in contact)", pointsInContact(p));
  return {{"contact", text}};
}

}  // namespace jello
