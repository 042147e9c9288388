// model/springfit.cpp: springs for a material (springfit.h).

#include "model/springfit.h"

#include <cmath>

namespace jello {

CubicStiffness latticeStiffness(const SpringConstants& springs, double h) {
  const double k1 = springs.k[int(SpringKind::Structural)], ks = springs.k[int(SpringKind::Shear)],
               kb = springs.k[int(SpringKind::Bend)];
  return {(k1 + 4 * kb + 10.0 / 3 * ks) / h, 7.0 / 3 * ks / h, 7.0 / 3 * ks / h};
}

namespace {

// |C|^2 of a cubic tensor over its 81 entries: 3 C11^2 + 6 C12^2 + 12 C44^2.
double squaredNorm(double c11, double c12, double c44) {
  return 3 * c11 * c11 + 6 * c12 * c12 + 12 * c44 * c44;
}

}  // namespace

SpringFit springsFor(const Material& m, double h) {
  SpringFit fit;
  const double mu = m.youngsModulus / 2.5;
  const double ks = 3.0 / 7 * mu * h, k1 = 11.0 / 35 * mu * h;
  fit.constants.k = {k1, ks, k1};
  for (int kind = 0; kind < kSpringKinds; ++kind)
    fit.constants.d[kind] = m.stiffnessDamping * fit.constants.k[kind];
  fit.youngsModulus = m.youngsModulus;
  const Lame lame = lameOf(m);
  const CubicStiffness c = latticeStiffness(fit.constants, h);
  fit.tensorResidual = std::sqrt(
      squaredNorm(c.c11 - (lame.lambda + 2 * lame.mu), c.c12 - lame.lambda, c.c44 - lame.mu) /
      squaredNorm(lame.lambda + 2 * lame.mu, lame.lambda, lame.mu));
  return fit;
}

}  // namespace jello
