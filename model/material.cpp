// model/material.cpp: the materials' stress and energy (material.h).

#include "model/material.h"

#include <algorithm>
#include <cmath>

#include "core/assert.h"

namespace jello {

const MaterialInfo& materialInfo(MaterialKind kind) {
  JELLO_ASSERT(int(kind) < int(kMaterials.size()));
  return kMaterials[int(kind)];
}

Lame lameOf(const Material& m) {
  const double e = m.youngsModulus, nu = m.poissonRatio;
  return {e / (2 * (1 + nu)), e * nu / ((1 + nu) * (1 - 2 * nu))};
}

namespace {

double neoHookeanLambda(Lame lame) { return lame.lambda + lame.mu; }

}  // namespace

double energyDensity(MaterialKind kind, Lame lame, const Mat3x3& f) {
  const double j = determinant(f);
  if (kind == MaterialKind::Corotated) {
    const Mat3x3 d = f - rotationOf(f);
    return lame.mu * contract(d, d) + 0.5 * lame.lambda * (j - 1) * (j - 1);
  }
  JELLO_ASSERT(kind == MaterialKind::NeoHookean);
  const double ic = contract(f, f);
  return 0.5 * lame.mu * (ic - 3) - lame.mu * (j - 1) +
         0.5 * neoHookeanLambda(lame) * (j - 1) * (j - 1);
}

Mat3x3 firstPiola(MaterialKind kind, Lame lame, const Mat3x3& f) {
  const double j = determinant(f);
  const Mat3x3 cof = cofactor(f);
  if (kind == MaterialKind::Corotated)
    return 2 * lame.mu * (f - rotationOf(f)) + lame.lambda * (j - 1) * cof;
  JELLO_ASSERT(kind == MaterialKind::NeoHookean);
  return lame.mu * f + (neoHookeanLambda(lame) * (j - 1) - lame.mu) * cof;
}

StressDerivative::StressDerivative(MaterialKind kind, Lame lame, const Mat3x3& f)
    : kind_(kind), lame_(lame), f_(f), cof_(cofactor(f)), j_(determinant(f)) {
  if (kind != MaterialKind::Corotated) return;
  const PolarDecomposition polar = polarDecomposition(f);
  rotation_ = polar.rotation;
  // (tr S I - S) has eigenvalues s1 + s2, s0 + s2, s0 + s1 on S's eigenvectors; its inverse, each
  // eigenvalue kept above the floor (where an inverted or collapsed element's rotation is
  // undefined, the derivative stays finite).
  const double s[3] = {polar.singular.x, polar.singular.y, polar.singular.z};
  const double floor = std::max(kSmallestSingularSum * std::fabs(s[0]), kSmallestSingularSum);
  const double inverse[3] = {1 / std::max(s[1] + s[2], floor), 1 / std::max(s[0] + s[2], floor),
                             1 / std::max(s[0] + s[1], floor)};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      double sum = 0;
      for (int k = 0; k < 3; ++k) sum += polar.axes(r, k) * inverse[k] * polar.axes(c, k);
      solve_(r, c) = sum;
    }
}

Mat3x3 StressDerivative::apply(const Mat3x3& df) const {
  const double dj = contract(cof_, df);
  const Mat3x3 dcof = cofactorChange(f_, df);
  if (kind_ == MaterialKind::Corotated) {
    // W S + S W = R^T dF - dF^T R for W = R^T dR = skew(w): (tr S I - S) w = 2 axial(R^T dF).
    const Vec3 w = solve_ * (2.0 * axial(transpose(rotation_) * df));
    const Mat3x3 dr = rotation_ * skew(w);
    return 2 * lame_.mu * (df - dr) + lame_.lambda * dj * cof_ + lame_.lambda * (j_ - 1) * dcof;
  }
  const double lambda = neoHookeanLambda(lame_);
  return lame_.mu * df + lambda * dj * cof_ + (lambda * (j_ - 1) - lame_.mu) * dcof;
}

namespace {

// S_d of a Green strain rate e: beta (2 mu e + lambda tr(e) I).
Mat3x3 viscousSecond(Lame lame, double beta, const Mat3x3& e) {
  return beta * (2 * lame.mu * e + lame.lambda * trace(e) * identity3());
}

}  // namespace

Mat3x3 viscousStress(Lame lame, double beta, const Mat3x3& f, const Mat3x3& fdot) {
  // E' = sym(F^T Fdot), written out: the kernel computes it for every element.
  double e[9];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      e[3 * i + j] = f.m[i] * fdot.m[j] + f.m[3 + i] * fdot.m[3 + j] + f.m[6 + i] * fdot.m[6 + j];
  Mat3x3 sd;
  const double volumetric = beta * lame.lambda * (e[0] + e[4] + e[8]);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      sd.m[3 * i + j] = beta * lame.mu * (e[3 * i + j] + e[3 * j + i]) + (i == j ? volumetric : 0);
  return f * sd;
}

Mat3x3 viscousStressByF(Lame lame, double beta, const Mat3x3& f, const Mat3x3& fdot,
                        const Mat3x3& df) {
  return df * viscousSecond(lame, beta, symmetric(transpose(f) * fdot)) +
         f * viscousSecond(lame, beta, symmetric(transpose(df) * fdot));
}

Mat3x3 viscousStressByRate(Lame lame, double beta, const Mat3x3& f, const Mat3x3& dfdot) {
  return f * viscousSecond(lame, beta, symmetric(transpose(f) * dfdot));
}

}  // namespace jello
