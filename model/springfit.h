// model/springfit.h: the bridge between the two models of a jelly (docs/physics.md, "Springs for
// a material"): the springs of a lattice whose small-strain response comes closest to an
// isotropic material's E and nu.
//
// Units: Pa for moduli, N/m for spring constants, N s/m for dampers, m for the spacing h.
//
// A lattice of spacing h with structural springs k1 (offsets along an axis), shear springs ks (face
// and body diagonals) and bend springs kb (two along an axis) is, at small strain away from its
// surface, a cubic solid of stiffnesses
//   C11 = (k1 + 4 kb + 10/3 ks) / h,   C12 = C44 = 7/3 ks / h
// (each spring of length l along unit n adds k l^2 n_i n_j n_k n_l / h^3). C12 = C44 always
// (Cauchy's relation of central forces), so the springs are an isotropic solid only with
// C11 = 3 C12: Poisson's ratio 1/4. The fit keeps that isotropic solid and E: mu' = E / 2.5,
// C11 = 3 mu', C12 = C44 = mu', with k1 = kb (as the course has one k), so
//   ks = 3/7 mu' h,   k1 = kb = 11/35 mu' h;
// and dampers d = beta k for each kind (beta the material's stiffness damping). Its residual is
// the difference in Poisson's ratio (nu - 1/4) and the relative Frobenius norm of the elasticity
// tensors' difference.
#pragma once

#include "model/material.h"
#include "model/springs.h"

namespace jello {

struct SpringFit {
  SpringConstants constants;
  double youngsModulus = 0;    // Pa, the springs' (E exactly)
  double poissonRatio = 0.25;  // the springs'
  double tensorResidual = 0;   // |C_springs - C_material| / |C_material| (Frobenius)
};
SpringFit springsFor(const Material& material, double spacing);

// The cubic stiffnesses (Pa) of a lattice's springs, as above: C11, C12, C44.
struct CubicStiffness {
  double c11 = 0, c12 = 0, c44 = 0;
};
CubicStiffness latticeStiffness(const SpringConstants& springs, double spacing);

}  // namespace jello
