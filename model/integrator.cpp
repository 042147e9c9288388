// model/integrator.cpp: the integrators' names (integrator.h), one per enumerator, in its order.

#include "model/integrator.h"

#include <array>
#include <cctype>

#include "core/assert.h"

namespace jello {

namespace {

constexpr std::array<const char*, kIntegratorCount> kNames = {
    "EULER", "SYMPLECTIC", "MIDPOINT", "VERLET", "RK4", "RK45", "IMPLICIT"};

constexpr bool everyIntegratorNamed() {
  for (const char* name : kNames)
    if (!name) return false;
  return true;
}
static_assert(everyIntegratorNamed(), "a name for every enumerator of Integrator, in its order");

}  // namespace

const char* integratorName(Integrator integrator) {
  const auto index = static_cast<std::size_t>(integrator);
  JELLO_ASSERT(index < kNames.size());
  return index < kNames.size() ? kNames[index] : "?";
}

std::string integratorNameList() {
  std::string list;
  for (std::size_t i = 0; i < kNames.size(); ++i) {
    list += i == 0 ? "" : i + 1 == kNames.size() ? " or " : ", ";
    list += kNames[i];
  }
  return list;
}

bool parseIntegratorName(std::string_view name, Integrator* out) {
  for (std::size_t i = 0; i < kNames.size(); ++i) {
    const std::string_view candidate = kNames[i];
    if (candidate.size() != name.size()) continue;
    bool same = true;
    for (std::size_t c = 0; c < name.size() && same; ++c)
      same = std::toupper(static_cast<unsigned char>(name[c])) == candidate[c];
    if (same) {
      *out = static_cast<Integrator>(i);
      return true;
    }
  }
  return false;
}

}  // namespace jello
