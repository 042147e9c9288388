// model/gravity.cpp: a scene's gravity: force, energy and description.

#include "model/gravity.h"

namespace jello {

void GravityTerm::addForcesOn(PointRange points, const double*, const double*, const Bounds*,
                              double* force) const {
  for (int q = points.begin; q < points.end; ++q) addAt(force, q, weight_);
}

void GravityTerm::summarise(std::vector<std::string>* kept, std::vector<std::string>*) const {
  kept->push_back("gravity");
}

std::vector<TermLine> GravityTerm::describe(const double*) const {
  return {{"gravity", textf("(%.6g, %.6g, %.6g) m/s^2 on every point", g_.x, g_.y, g_.z)}};
}

}  // namespace jello
