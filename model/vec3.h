// vec3.h: a small 3-vector of doubles for the force terms.
// Units follow the caller (metres, metres per second, newtons).
#pragma once

#include <cmath>

namespace jello {

// The one pi of the project.
constexpr double kPi = 3.14159265358979323846;

struct Vec3 {
  double x = 0, y = 0, z = 0;
};

inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.z}; }
inline Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline Vec3& operator+=(Vec3& a, Vec3 b) {
  a.x += b.x;
  a.y += b.y;
  a.z += b.z;
  return a;
}
inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline double length(Vec3 a) { return std::sqrt(dot(a, a)); }
inline Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// Returns L/|L| and writes |L|; a zero vector gives a zero direction. The one place where
// zero-length vectors are dealt with: every force term built on it exerts no force along a
// direction it cannot define. (A select, not a branch, so that the spring loop vectorises.)
inline Vec3 direction(Vec3 L, double* len) {
  *len = length(L);
  const double inverse = *len != 0 ? 1.0 / *len : 0.0;
  return inverse * L;
}

// Whether x lies in the box [lower, upper] on every axis, both ends included (a region pin, the
// panel's pin region, a jelly inside its bounding box).
inline bool inBox(Vec3 x, Vec3 lower, Vec3 upper) {
  return x.x >= lower.x && x.x <= upper.x && x.y >= lower.y && x.y <= upper.y && x.z >= lower.z &&
         x.z <= upper.z;
}

}  // namespace jello
