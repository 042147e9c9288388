// model/gravity.h: a scene's gravity, a uniform acceleration g (m/s^2) on every point,
// everywhere (a course world fakes gravity with a uniform field, which acts inside the box only).
// A point term: the force is mass * g, N.
#pragma once

#include <vector>

#include "model/term.h"

namespace jello {

class GravityTerm final : public ForceTerm {
 public:
  GravityTerm(int points, Vec3 g, double mass) : ForceTerm(points), g_(g), weight_(mass * g) {}
  // Points of different masses (a scene's jellies): each point's weight its own mass times g.
  GravityTerm(Vec3 g, const std::vector<double>& pointMass);
  bool mayReach(const Bounds&) const override { return true; }
  void addForcesOn(PointRange points, const double* p, const double* v, const Bounds* box,
                   double* force) const override;
  void addJacobian(const double*, const double*, JacobianSink*) const override {}
  // Stores none, as the field: the divergence guard bounds the work of its largest force instead
  // (a potential -m g . p would make the guard's energy negative, and its bound meaningless).
  void addEnergy(const double*, double*) const override {}
  double largestExternalForce() const override;
  void summarise(std::vector<std::string>* kept, std::vector<std::string>* leftOut) const override;
  std::vector<TermLine> describe(const double* p) const override;

 private:
  Vec3 g_, weight_;
  std::vector<Vec3> weights_;  // by point, when the masses differ; else empty and weight_ it is
};

}  // namespace jello
