// model/integrator.h: the integrators by name, as world files and command lines write them. What
// each one does, and its step, is the integrator table's (solver/integrators.h), one row per
// enumerator in this order; the names are here, below the readers that need them.
#pragma once

#include <string>
#include <string_view>

namespace jello {

// The integrators, in the order every listing of them uses: first order first.
enum class Integrator { Euler, Symplectic, Midpoint, Verlet, RK4, RK45, Implicit };
// IMPLICIT stays last: the count is taken from it (the tables static_assert they have this many
// rows).
constexpr int kIntegratorCount = static_cast<int>(Integrator::Implicit) + 1;

// Canonical upper-case name, as written in world files.
const char* integratorName(Integrator integrator);
// "EULER, SYMPLECTIC, ... or IMPLICIT": every accepted name, in order, for messages.
std::string integratorNameList();
// Case-insensitive lookup of a name; false when the name is none of them.
bool parseIntegratorName(std::string_view name, Integrator* out);

}  // namespace jello
