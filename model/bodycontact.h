// model/bodycontact.h: contact between jellies, and of a jelly with itself (docs/physics.md,
// "Contact between bodies"). A pair term whose pairs are found anew from the positions.
//
// Formulation: every surface point is a ball of radius r (half its body's spacing, or half the
// scene's contact distance). Two balls that overlap, of different bodies or of one body with
// self-contact whose grid indices differ by more than kSelfNeighbourhood along some axis, push
// apart with the law a sphere obstacle pushes a point with (obstacle.h), the sphere of radius
// D = r_a + r_b about the other point:
//   L = p_a - p_b, w = v_a - v_b, depth = D - |L| > 0, n = L / |L|,
//   F_a = k depth n - d (w . n) n + F_t(N = k depth - d w . n, n, w),  F_b = -F_a,
// F_t the obstacles' regularised Coulomb friction on the relative velocity. F_a depends on L and w
// alone: momentum is conserved exactly (and angular momentum, F being along L without friction),
// and the Jacobian blocks are the sphere obstacle's, dF/dL and dF/dw.
//
// Broad phase: a part's surface points are candidates where they lie within another part's
// bounding box grown by max D (all of them with self-contact); the candidates are sorted by the
// cell of a grid of edge max D that holds them, and each looks in its own and the 26 neighbouring
// cells (9 runs of consecutive keys): O(P log P) for P candidates, rebuilt at every evaluation (no
// state kept, so every evaluation and every range of points sees the same pairs). The pairs come
// sorted (a < b, by a, then b).
//
// Units: metres, seconds, newtons; k in N/m, d in N s/m. Signs as model/term.h.
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "model/body.h"
#include "model/obstacle.h"
#include "model/scenespec.h"
#include "model/term.h"

namespace jello {

// Points of one body this close in every grid axis never touch by self-contact: at rest they
// are at most this many spacings apart along an axis, closer than any contact distance lets them
// be without pushing, so their springs alone keep them apart.
constexpr int kSelfNeighbourhood = 2;

// A point a takes at most this many pairs with points b > a: the first it finds, in the broad
// phase's order (the 27 cells by dx, then dy, then dz from -1 to 1; in a cell, by point). A
// surface point touches a few others at rest and a dozen or so in a hard crush; a state that puts
// thousands at one place (two jellies collapsed onto a point) would otherwise make the contact's
// work quadratic (15 s a step for two 20^3 jellies against 0.07 s).
constexpr int kMostContactPartners = 64;

// Each part (jelly) of the body as the contact sees it.
struct ContactPart {
  double radius = 0;  // m, its points' balls
  bool selfContact = false;
};

// One pair in contact: points a < b, their contact distance.
struct ContactPair {
  int a = 0, b = 0;
  double distance = 0;
};

class BodyContactTerm final : public ForceTerm {
 public:
  // The contact of the parts of `body` (its parts, or the body alone as one part).
  BodyContactTerm(const Body& body, std::vector<ContactPart> parts, const BodyContactSpec& spec);

  // The pairs in contact at positions p, sorted.
  std::vector<ContactPair> contacts(const double* p) const;
  // The same into `found` (its storage reused).
  void findContacts(const double* p, std::vector<ContactPair>* found) const;
  // The force on a of a pair at (L, w) and its derivatives.
  Vec3 pairForce(const ContactPair& pair, Vec3 L, Vec3 w) const;
  // The closest approach of two parts at p: the smallest |p_a - p_b| over the pairs in contact of
  // points of different parts, m; infinity when none touch (every such pair is then at least its
  // contact distance apart) and with one part.
  double smallestGap(const double* p) const;

  bool isPairTerm() const override { return true; }
  bool pairsMove() const override { return true; }
  std::vector<std::pair<int, int>> pairsAt(const double* p) const override;
  bool mayReach(const Bounds&) const override { return true; }
  int pointsInContact(const double* p) const override;
  void addForcesOn(PointRange points, const double* p, const double* v, const Bounds* box,
                   double* force) const override;
  void addJacobian(const double* p, const double* v, JacobianSink* sink) const override;
  void addEnergy(const double* p, double* energy) const override;
  void summarise(std::vector<std::string>* kept, std::vector<std::string>* leftOut) const override;
  std::vector<TermLine> describe(const double* p) const override;

 private:
  // The sphere obstacle a pair's law is: radius D about the origin (L seen from b).
  Obstacle ballOf(const ContactPair& pair) const;
  bool mayTouch(int a, int b) const;
  // The candidates that may touch at p: every point of a part with self-contact, and the points
  // of the others within reach of another part's bounding box (`boxes`: each part's, scratch).
  void activeCandidates(const double* p, std::vector<Bounds>* boxes,
                        std::vector<int>* active) const;
  // contacts(p) in this thread's buffer, valid until its next call on this thread: what the force,
  // Jacobian and energy go through, allocating nothing once the buffer is grown.
  const std::vector<ContactPair>& contactsNow(const double* p) const;

  std::vector<ContactPart> parts_;
  Obstacle law_;                            // the spring and the friction
  std::vector<int> candidates_;             // the surface points, ascending
  std::vector<int> partOf_;                 // point -> part
  std::vector<std::array<int, 3>> gridOf_;  // point -> its grid index in its part
  std::vector<double> radiusOf_;            // point -> its ball's radius, m
  double cell_ = 0;                         // m, the broad phase's cell edge
};

}  // namespace jello
