// model/gravity.cpp: a scene's gravity: force, energy and description.

#include "model/gravity.h"

#include <algorithm>

namespace jello {

GravityTerm::GravityTerm(Vec3 g, const std::vector<double>& pointMass)
    : ForceTerm(static_cast<int>(pointMass.size())), g_(g) {
  for (double mass : pointMass) weights_.push_back(mass * g);
}

double GravityTerm::largestExternalForce() const {
  double largest = length(weight_);
  for (Vec3 w : weights_) largest = std::max(largest, length(w));
  return largest;
}

void GravityTerm::addForcesOn(PointRange points, const double*, const double*, const Bounds*,
                              double* force) const {
  if (!weights_.empty()) {
    for (int q = points.begin; q < points.end; ++q) addAt(force, q, weights_[q]);
    return;
  }
  for (int q = points.begin; q < points.end; ++q) addAt(force, q, weight_);
}

void GravityTerm::summarise(std::vector<std::string>* kept, std::vector<std::string>*) const {
  kept->push_back("gravity");
}

std::vector<TermLine> GravityTerm::describe(const double*) const {
  return {{"gravity", textf("(%.6g, %.6g, %.6g) m/s^2 on every point", g_.x, g_.y, g_.z)}};
}

}  // namespace jello
