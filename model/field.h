// model/field.h: the world's force field, a point term: forces given on an R^3 grid of nodes
// spanning the box, interpolated trilinearly inside it, zero outside (docs/world-format.md has
// the node layout, docs/physics.md the interpolation).
//
// Units: metres, newtons. The field stores no energy: the divergence guard bounds what it can
// supply by its largest node.
#pragma once

#include <vector>

#include "model/term.h"

namespace jello {

// A field's nodes without owning them (a ForceField's, or a term's view of one).
struct FieldView {
  const double* forces = nullptr;  // 3 doubles a node, as ForceField::forces
  int resolution = 0;
  FieldView() = default;
  FieldView(const double* f, int r) : forces(f), resolution(r) {}
  FieldView(const ForceField& field)
      : forces(field.forces.data()), resolution(field.resolution) {}  // NOLINT: a view
  std::size_t nodes() const {
    return static_cast<std::size_t>(resolution) * resolution * resolution;
  }
  Vec3 node(std::size_t n) const { return {forces[3 * n], forces[3 * n + 1], forces[3 * n + 2]}; }
};

// What the kernel needs of a field: Absent at resolution 0, Zero when every node is exactly
// zero, Uniform when every node is exactly the same force (node 0's), Trilinear otherwise.
enum class FieldUse { Absent, Zero, Uniform, Trilinear };
FieldUse fieldUse(FieldView field);

// The force field at p: trilinear inside the box (walls included), zero outside.
Vec3 fieldForce(const ForceField& field, Vec3 p);
// Derivative of fieldForce with respect to p: the gradient of the trilinear interpolation
// inside the point's cell; zero outside the box and for R < 2.
Block3 fieldJacobian(const ForceField& field, Vec3 p);

// The position (m) of field node (i,j,k) along one axis for resolution r >= 2.
double fieldNodeCoordinate(int index, int resolution);

enum class FieldKind { Zero, Uniform, Swirl, Radial, General };
const char* fieldKindName(FieldKind kind);
// What a force field is: zero, uniform F, swirl F = s (-y, x, 0), radial F = s (x, y, z), or
// general, recognised to within the six-decimal rounding of the course's files.
struct FieldShape {
  FieldKind kind = FieldKind::Zero;
  Vec3 uniform;                      // N, for Uniform
  double strength = 0;               // N/m, for Swirl and Radial
  double smallest = 0, largest = 0;  // |F| over the nodes, N
};
FieldShape classifyField(FieldView field);

// The field as the kernel computes it. The term reads the world's node array (for the reference
// force and the Jacobian): that array must outlive the term and stay where it is (moving the
// World that holds it keeps it in place).
class FieldTerm final : public ForceTerm {
 public:
  // How the force is computed: a constant (a uniform field), the interpolation on a padded copy
  // of the nodes (4 doubles each, so that two points' nodes make one Pack; 8 points at a time,
  // the same bits as the reference), or the reference interpolation on the world's nodes point
  // by point (the general kernel).
  enum class Method { Uniform, Padded, Reference };
  // `mass` (kg, each point's) only for the description: the acceleration a force gives.
  FieldTerm(int points, const ForceField& field, double mass, Method method);

  // The field acts inside the box only.
  bool mayReach(const Bounds& box) const override;
  void addForcesOn(PointRange points, const double* p, const double* v, const Bounds* box,
                   double* force) const override;
  void addJacobian(const double* p, const double* v, JacobianSink* sink) const override;
  void addEnergy(const double*, double*) const override {}
  double largestExternalForce() const override { return largestNode_; }
  void summarise(std::vector<std::string>* kept, std::vector<std::string>* leftOut) const override;
  std::vector<TermLine> describe(const double* p) const override;

 private:
  FieldView field_;  // the world's nodes
  Method method_;
  double mass_;                 // kg, a point's
  Vec3 uniform_;                // N, for Method::Uniform
  std::vector<double> padded_;  // for Method::Padded: (x, y, z, 0) a node
  double largestNode_ = 0;      // N
};

}  // namespace jello
