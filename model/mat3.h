// model/mat3.h: 3x3 matrices for the finite elements (material.h, elements.h): deformation
// gradients, stresses, rotations. Row-major, m[3 * row + column]; no Eigen in the model.
//
// Units are the caller's: a deformation gradient has none, a stress is in Pa.
#pragma once

#include "model/vec3.h"

namespace jello {

struct Mat3x3 {
  double m[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
  double operator()(int row, int column) const { return m[3 * row + column]; }
  double& operator()(int row, int column) { return m[3 * row + column]; }
  Vec3 column(int c) const { return {m[c], m[3 + c], m[6 + c]}; }
  Vec3 row(int r) const { return {m[3 * r], m[3 * r + 1], m[3 * r + 2]}; }
  void setColumn(int c, Vec3 v) {
    m[c] = v.x;
    m[3 + c] = v.y;
    m[6 + c] = v.z;
  }
};

inline Mat3x3 identity3() {
  Mat3x3 a;
  a.m[0] = a.m[4] = a.m[8] = 1;
  return a;
}
inline Mat3x3 fromColumns(Vec3 a, Vec3 b, Vec3 c) {
  Mat3x3 out;
  out.setColumn(0, a);
  out.setColumn(1, b);
  out.setColumn(2, c);
  return out;
}
inline Mat3x3 operator+(const Mat3x3& a, const Mat3x3& b) {
  Mat3x3 out;
  for (int e = 0; e < 9; ++e) out.m[e] = a.m[e] + b.m[e];
  return out;
}
inline Mat3x3 operator-(const Mat3x3& a, const Mat3x3& b) {
  Mat3x3 out;
  for (int e = 0; e < 9; ++e) out.m[e] = a.m[e] - b.m[e];
  return out;
}
inline Mat3x3 operator*(double s, const Mat3x3& a) {
  Mat3x3 out;
  for (int e = 0; e < 9; ++e) out.m[e] = s * a.m[e];
  return out;
}
inline Mat3x3 operator*(const Mat3x3& a, const Mat3x3& b) {
  Mat3x3 out;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      out.m[3 * i + j] =
          a.m[3 * i] * b.m[j] + a.m[3 * i + 1] * b.m[3 + j] + a.m[3 * i + 2] * b.m[6 + j];
  return out;
}
inline Vec3 operator*(const Mat3x3& a, Vec3 x) {
  return {dot(a.row(0), x), dot(a.row(1), x), dot(a.row(2), x)};
}
inline Mat3x3 transpose(const Mat3x3& a) {
  Mat3x3 out;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out.m[3 * i + j] = a.m[3 * j + i];
  return out;
}
inline double trace(const Mat3x3& a) { return a.m[0] + a.m[4] + a.m[8]; }
// The sum of the entries' products, A : B.
inline double contract(const Mat3x3& a, const Mat3x3& b) {
  double s = 0;
  for (int e = 0; e < 9; ++e) s += a.m[e] * b.m[e];
  return s;
}
inline double determinant(const Mat3x3& a) {
  return dot(a.column(0), cross(a.column(1), a.column(2)));
}
// The cofactor matrix, dJ/dF for J = det F: its columns are f1 x f2, f2 x f0, f0 x f1 of F's
// columns f0, f1, f2.
inline Mat3x3 cofactor(const Mat3x3& f) {
  const Vec3 a = f.column(0), b = f.column(1), c = f.column(2);
  return fromColumns(cross(b, c), cross(c, a), cross(a, b));
}
// The derivative of cofactor(F) in the direction dF.
inline Mat3x3 cofactorChange(const Mat3x3& f, const Mat3x3& df) {
  const Vec3 a = f.column(0), b = f.column(1), c = f.column(2);
  const Vec3 da = df.column(0), db = df.column(1), dc = df.column(2);
  return fromColumns(cross(db, c) + cross(b, dc), cross(dc, a) + cross(c, da),
                     cross(da, b) + cross(a, db));
}
// The inverse; the caller makes sure that det a is not zero.
inline Mat3x3 inverse(const Mat3x3& a) { return (1.0 / determinant(a)) * transpose(cofactor(a)); }
// The symmetric part (A + A^T) / 2.
inline Mat3x3 symmetric(const Mat3x3& a) { return 0.5 * (a + transpose(a)); }
// The matrix of the cross product with w: skew(w) x = w x x.
inline Mat3x3 skew(Vec3 w) {
  Mat3x3 out;
  out.m[1] = -w.z, out.m[2] = w.y, out.m[3] = w.z, out.m[5] = -w.x, out.m[6] = -w.y, out.m[7] = w.x;
  return out;
}
// The w of a skew matrix (its antisymmetric part's): (a21 - a12, a02 - a20, a10 - a01) / 2.
inline Vec3 axial(const Mat3x3& a) {
  return {0.5 * (a.m[7] - a.m[5]), 0.5 * (a.m[2] - a.m[6]), 0.5 * (a.m[3] - a.m[1])};
}
// The unit matrix E_rc: 1 at (row, column), 0 elsewhere.
inline Mat3x3 unitMatrix(int row, int column) {
  Mat3x3 out;
  out.m[3 * row + column] = 1;
  return out;
}

// The rotation R and the symmetric S of F = R S with det R = +1 (for det F < 0, S has one negative
// eigenvalue: the one of the smallest magnitude), from the eigenvectors of F^T F (Jacobi's
// rotations). Also S's eigenvalues, F's signed singular values, largest first, and S's
// eigenvectors, the columns of `axes` (a rotation) in the same order: S = axes diag(singular)
// axes^T.
struct PolarDecomposition {
  Mat3x3 rotation, stretch, axes;
  Vec3 singular;
};
PolarDecomposition polarDecomposition(const Mat3x3& f);
// R of F = R S alone, the same rotation: for det F > 0 by Higham's scaled Newton iteration
// R <- (g R + R^-T / g) / 2 (g = |det R|^(-1/3) while det R is beyond 1 +- 0.1, else 1), until
// a step changes R by less than 1e-8 (its squared entries' sum below 1e-16; the iteration
// converges quadratically, so R is then exact to rounding: 2 to 4 steps at a jelly's strains);
// for det F <= 1e-6 |F|^3, from polarDecomposition.
Mat3x3 rotationOf(const Mat3x3& f);

}  // namespace jello
