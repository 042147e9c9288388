// model/material.h: what a jelly is made of (docs/physics.md, "Finite elements"): the course's
// springs, or an elastic solid described in physical units and simulated with finite elements.
//
// Units: Young's modulus and stresses in Pa (N/m^2), density in kg/m^3, energy densities in
// J/m^3, the Rayleigh damping's mass coefficient in 1/s and its stiffness coefficient in s.
// A deformation gradient F = dx/dX (current over rest positions) has no unit. Stresses are the
// first Piola-Kirchhoff stress P = dPsi/dF: force per unit rest area.
#pragma once

#include <array>
#include <cstdint>

#include "model/mat3.h"

namespace jello {

enum class MaterialKind : std::uint8_t { Springs, Corotated, NeoHookean };
struct MaterialInfo {
  MaterialKind kind;
  const char* name;  // the scene file's `material = "..."`
  const char* what;  // in a description
};
inline constexpr std::array<MaterialInfo, 3> kMaterials = {{
    {MaterialKind::Springs, "springs", "the course's springs"},
    {MaterialKind::Corotated, "corotated", "fixed corotated elasticity"},
    {MaterialKind::NeoHookean, "neohookean", "stable Neo-Hookean elasticity"},
}};
static_assert(kMaterials[int(MaterialKind::NeoHookean)].kind == MaterialKind::NeoHookean);
const MaterialInfo& materialInfo(MaterialKind kind);

// The Poisson's ratios a material may have. At 0.5 it could not change its volume at all (lambda
// infinite), and near it linear tetrahedra lock; at -1 its bulk modulus lambda + 2 mu / 3 is 0.
// Below 0 it is auxetic (lambda < 0: it widens under tension): the stable Neo-Hookean energy holds
// that (its lambda' = lambda + mu = mu / (1 - 2 nu) > 0), the corotated one does not (its
// lambda/2 (J - 1)^2 goes below zero at a large stretch), so it keeps nu >= 0.
constexpr double kSmallestPoissonRatio = -0.99;
constexpr double kLargestPoissonRatio = 0.49;
constexpr double smallestPoissonRatio(MaterialKind kind) {
  return kind == MaterialKind::NeoHookean ? kSmallestPoissonRatio : 0.0;
}

struct Material {
  MaterialKind kind = MaterialKind::Springs;
  double youngsModulus = 0;     // E, Pa, > 0
  double poissonRatio = 0;      // nu, smallestPoissonRatio(kind) <= nu <= kLargestPoissonRatio
  double density = 0;           // kg/m^3, > 0
  double massDamping = 0;       // Rayleigh's alpha, 1/s: a force -alpha m v on every point
  double stiffnessDamping = 0;  // Rayleigh's beta, s: the viscous stress below
  bool elements() const { return kind != MaterialKind::Springs; }
};

// Lame's constants of E and nu: mu = E / (2 (1 + nu)), lambda = E nu / ((1 + nu)(1 - 2 nu)).
struct Lame {
  double mu = 0, lambda = 0;
};
Lame lameOf(const Material& m);

// The elastic energy density Psi(F), J/m^3, zero at rest (F = I or any rotation):
//   corotated:  mu |F - R|^2 + lambda/2 (J - 1)^2, R the rotation of F = R S (mat3.h);
//   neohookean: mu/2 (I_C - 3) - mu (J - 1) + lambda'/2 (J - 1)^2, I_C = |F|^2, J = det F,
//               lambda' = lambda + mu (so that both give Lame's response at small strain).
double energyDensity(MaterialKind kind, Lame lame, const Mat3x3& f);
// P = dPsi/dF, Pa:
//   corotated:  2 mu (F - R) + lambda (J - 1) cof F;
//   neohookean: mu F - mu cof F + lambda' (J - 1) cof F.
Mat3x3 firstPiola(MaterialKind kind, Lame lame, const Mat3x3& f);

// The derivative of P at F, applied to changes dF: dP = dP/dF : dF, exactly (for the corotated,
// with dR = R skew(w), (tr S I - S) w = 2 axial(R^T dF); where two singular values sum to under
// kSmallestSingularSum of the largest (or under kSmallestSingularSum), the sum is taken as that,
// so that a flat, inverted or collapsed element's derivative stays finite). Built once per F,
// applied to as many dF as asked.
constexpr double kSmallestSingularSum = 1e-6;
class StressDerivative {
 public:
  StressDerivative(MaterialKind kind, Lame lame, const Mat3x3& f);
  Mat3x3 apply(const Mat3x3& df) const;

 private:
  MaterialKind kind_;
  Lame lame_;
  Mat3x3 f_, cof_, rotation_, solve_;  // solve_ = (tr S I - S)^-1
  double j_ = 1;
};

// Rayleigh's stiffness damping made independent of rotation: the viscous first Piola-Kirchhoff
// stress P_d = F S_d, S_d = beta (2 mu E' + lambda tr(E') I), E' = sym(F^T Fdot) the rate of the
// Green strain (zero for any rigid motion). At small strain it is beta K v, K the stiffness.
Mat3x3 viscousStress(Lame lame, double beta, const Mat3x3& f, const Mat3x3& fdot);
// Its change with F (Fdot fixed) and with Fdot (F fixed), in directions dF and dFdot.
Mat3x3 viscousStressByF(Lame lame, double beta, const Mat3x3& f, const Mat3x3& fdot,
                        const Mat3x3& df);
Mat3x3 viscousStressByRate(Lame lame, double beta, const Mat3x3& f, const Mat3x3& dfdot);

}  // namespace jello
