// io/fieldrecipe.cpp: a force field from a recipe (fieldrecipe.h). Expressions are evaluated
// by muparser.

#include "io/fieldrecipe.h"

#include <muParser.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "model/field.h"

namespace jello {

namespace {

void fillNodes(ForceField& field, int r, const std::function<Vec3(Vec3)>& force) {
  field.resolution = r;
  field.forces.assign(3 * static_cast<std::size_t>(r) * r * r, 0.0);
  for (int i = 0; i < r; ++i)
    for (int j = 0; j < r; ++j)
      for (int k = 0; k < r; ++k) {
        Vec3 p = r == 1 ? Vec3{}
                        : Vec3{fieldNodeCoordinate(i, r), fieldNodeCoordinate(j, r),
                               fieldNodeCoordinate(k, r)};
        field.setNode((i * r + j) * r + k, force(p));
      }
}

std::string trim(const std::string& s) {
  std::size_t first = s.find_first_not_of(" \t"), last = s.find_last_not_of(" \t");
  return first == std::string::npos ? std::string() : s.substr(first, last - first + 1);
}

// "fx; fy; fz" cut at its semicolons, each part trimmed; refused unless there are three.
std::vector<std::string> splitExpressions(const std::string& expression, const std::string& label) {
  std::vector<std::string> parts;
  std::string rest = expression;
  for (std::size_t semicolon; (semicolon = rest.find(';')) != std::string::npos;) {
    parts.push_back(trim(rest.substr(0, semicolon)));
    rest = rest.substr(semicolon + 1);
  }
  parts.push_back(trim(rest));
  if (parts.size() != 3) {
    throw InputError(label + (label.empty() ? "" : " ") +
                     "needs three expressions \"fx; fy; fz\", got " + std::to_string(parts.size()));
  }
  return parts;
}

// The nodes of an R^3 field, each force the value of the three expressions at the node.
void fillFromExpressions(ForceField& field, int r, const std::string& expression,
                         const std::string& label) {
  const std::vector<std::string> parts = splitExpressions(expression, label);
  const std::string prefix = label.empty() ? "" : label + ": ";
  double x = 0, y = 0, z = 0;  // the variables the parsers read, set node by node below
  mu::Parser parsers[3];
  const char* names[3] = {"fx", "fy", "fz"};
  for (int c = 0; c < 3; ++c) {
    try {
      parsers[c].DefineVar("x", &x);
      parsers[c].DefineVar("y", &y);
      parsers[c].DefineVar("z", &z);
      parsers[c].SetExpr(parts[c]);
      parsers[c].Eval();  // parse now, so that errors name the expression, not a node
    } catch (const mu::Parser::exception_type& e) {
      throw InputError(prefix + names[c] + ": " + e.GetMsg());
    }
  }
  fillNodes(field, r, [&](Vec3 p) {
    x = p.x;
    y = p.y;
    z = p.z;
    double value[3];
    for (int c = 0; c < 3; ++c) {
      value[c] = parsers[c].Eval();
      if (!std::isfinite(value[c])) {
        char where[96];
        std::snprintf(where, sizeof where, "(%g, %g, %g)", p.x, p.y, p.z);
        throw InputError(prefix + names[c] + " is not finite at " + where);
      }
    }
    return Vec3{value[0], value[1], value[2]};
  });
}

}  // namespace

ForceField buildField(const FieldRecipe& recipe) {
  using Source = FieldRecipe::Source;
  ForceField field;
  const int r = recipe.resolution;
  if (recipe.source == Source::Given) return recipe.given;
  if (recipe.source == Source::None || r == 0) return field;
  if (r < 0 || r > kMaxResolution) {
    throw InputError("field resolution " + std::to_string(r) + " is out of range (0 to " +
                     std::to_string(kMaxResolution) + ")");
  }
  if (r == 1 && recipe.source != Source::Uniform) {
    throw InputError(
        "a field that varies in space needs --field-resolution 2 or more (1 is one uniform force)");
  }
  switch (recipe.source) {
    case Source::Uniform:
      fillNodes(field, r, [&](Vec3) { return recipe.uniform; });
      break;
    case Source::Swirl:
      fillNodes(field, r, [&](Vec3 p) { return recipe.strength * Vec3{-p.y, p.x, 0}; });
      break;
    case Source::Radial:
      fillNodes(field, r, [&](Vec3 p) { return recipe.strength * p; });
      break;
    case Source::Expression:
      fillFromExpressions(field, r, recipe.expression, recipe.label);
      break;
    case Source::None:   // returned above
    case Source::Given:  // returned above
      break;
  }
  return field;
}

}  // namespace jello
