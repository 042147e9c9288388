// model/elements.h: linear tetrahedral finite elements (docs/physics.md, "Finite elements"): the
// elastic and viscous forces of the jellies made of a material in physical units (material.h), a
// pair term (its forces join four points at once).
//
// Units: metres, seconds, kilograms, newtons, pascals. Each element is a tetrahedron of rest
// positions X_0..X_3 (body.h Tet) and rest volume V. Its deformation gradient is
// F = sum_a x_a b_a^T, where b_1, b_2, b_3 are the rows of Dm^-1 (Dm = [X1-X0, X2-X0, X3-X0]) and
// b_0 = -(b_1 + b_2 + b_3); its rate Fdot = sum_a v_a b_a^T. Its force ON point a is
// f_a = -V (P(F) + P_d(F, Fdot)) b_a, P the material's stress, P_d the viscous stress; a point of
// a part with Rayleigh mass damping alpha also gets -alpha m v. The elastic energy is
// sum V Psi(F).
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "model/body.h"
#include "model/material.h"
#include "model/term.h"

namespace jello {

// The mean of the lumped masses (density * volume / 4 a tetrahedron's point) of a body that is
// not joined, made of `material`, kg a point: density * restVolume / points.
double meanElementMass(const Body& body, const Material& material);

class ElementTerm final : public ForceTerm {
 public:
  // The elements of every part of `body` whose material is elements (byPart[p] is part p's
  // material; one for a body that is not joined), in part order, each part's tetrahedraOf; and
  // each point's mass, kg (for the mass damping).
  ElementTerm(const Body& body, std::vector<Material> byPart, const std::vector<double>& pointMass);

  int elementCount() const { return static_cast<int>(elements_.size()); }
  const Tet& element(int e) const { return elements_[e].t; }
  double restVolume(int e) const { return elements_[e].volume; }
  const Material& materialOf(int e) const { return material_[elements_[e].part]; }
  // The element's deformation gradient at positions p.
  Mat3x3 deformation(int e, const double* p) const;
  // The von Mises equivalent of the element's Cauchy stress sigma = P F^T / J at p, Pa (the
  // elastic stress; 0 for a collapsed element).
  double vonMises(int e, const double* p) const;

  bool isPairTerm() const override { return true; }
  std::vector<std::pair<int, int>> couplings() const override { return couplings_; }
  std::size_t couplingCount() const override { return couplings_.size(); }
  bool mayReach(const Bounds&) const override { return true; }
  // On a range of points, the elements that have a point in it, in their order, each adding its
  // force to its points in the range: each point's sum is over its elements in their order,
  // whatever the range, so that every range rounds as the whole call.
  void addForcesOn(PointRange points, const double* p, const double* v, const Bounds* box,
                   double* force) const override;
  void addJacobian(const double* p, const double* v, JacobianSink* sink) const override;
  void addEnergy(const double* p, double* energy) const override;
  void summarise(std::vector<std::string>* kept, std::vector<std::string>* leftOut) const override;
  std::vector<TermLine> describe(const double* p) const override;

 private:
  struct Element {
    Tet t;
    Vec3 b[4];
    double volume;
    int part;
  };
  // The element's stress P + P_d at (p, v).
  Mat3x3 stress(const Element& el, const double* p, const double* v) const;
  Mat3x3 gradientOf(const Element& el, const double* a) const;
  // The first and last element of each point, and the Jacobian's couplings and slots.
  void indexElements(int n);

  std::vector<Element> elements_;
  std::vector<Material> material_;  // by part
  std::vector<Lame> lame_;          // by part
  std::vector<double> damping_;     // each point's alpha m, N s/m
  bool massDamping_ = false;
  // The first and last element each point belongs to (-1 for none).
  std::vector<int> firstElement_, lastElement_;
  // The Jacobian's blocks, and each element's 16 in it (row a, column c at 4 a + c).
  std::vector<std::pair<int, int>> couplings_;
  std::vector<std::array<int, 16>> slots_;
};

}  // namespace jello
