// analysis/steplimits.h: the largest stable step of an integrator over a world's modes
// (modes.h), the margins a verdict keeps below it, the limits observed in real runs, and the
// worlds beyond what doubles can simulate.
#pragma once

#include <string>
#include <vector>

#include "analysis/modes.h"
#include "model/world.h"
#include "solver/physics.h"

namespace jello {

// Integrators with a bounded stable step, in table order (integratorsWithStepLimit()).
extern const std::vector<Integrator> kExplicitIntegrators;

// A mode counts as bounded when it grows by less than a factor of 2 over kHorizon: explicit
// Euler amplifies an undamped slow mode (a field's slight restoring force, say) at any step,
// but by so little that no run would see it.
constexpr double kHorizon = 10.0;  // s

// The largest dt at which `integrator` keeps every mode bounded; +infinity for IMPLICIT; 0 when
// it is below kShortestResolvedStep (a mode faster than about 1e18 rad/s).
double criticalStep(Integrator integrator, const std::vector<Mode>& modes);
// The shortest limit criticalStep resolves: 2^-60 s, 60 halvings of its largest step, 1 s.
constexpr double kShortestResolvedStep = 8.673617379884035e-19;

// Why the world's numbers are beyond what double arithmetic can simulate, "" when they are not:
// a rate per kilogram (kElastic, dElastic, kCollision or dCollision over the mass, or the
// largest field force over it) that is not finite with a factor kHeadroom to spare, or an
// initial velocity whose square is not. Such a world's forces overflow at its first step
// whatever the step; no eigen-analysis is run on it (its matrix would hold inf or NaN, on which
// the eigensolver spends minutes for nothing). Takes microseconds.
std::string beyondDoubles(const World& world, const State& initial);
// The margin beyondDoubles keeps: stretches up to the guard's 200 m times the ~50 springs on a
// point, and the sums of the integrators' stages, stay finite.
constexpr double kHeadroom = 1e6;

// The verdict's margin. The limits are those of small motions about a fixed state; a cube's own
// large motion modulates its springs' stiffness, and a fast mode with little damping can be
// pumped by that modulation (parametric resonance) at steps the frozen analysis calls stable:
// undamped rotate.w with its corner pulled out by 0.17 or 0.35 m diverges under SYMPLECTIC at
// 0.91 or 0.82 of the predicted limit, stretched by 30% at 0.58 of it, while the highest
// frequency along those motions stays within 1% of the prediction's. So a step is called
// stable below kStableFraction of the limit, and, for a cube whose fast modes are lightly
// damped and which starts deformed, only below kLargeMotionStableFraction of it; above that it
// is marginal.
constexpr double kStableFraction = 0.8;
constexpr double kLargeMotionStableFraction = 0.5;
// Lightly damped: the fastest mode at rest loses less than this fraction of its amplitude per
// radian (damping rate / frequency). Deformed: some spring strained by more than kDeformed.
constexpr double kLightDamping = 0.02;
constexpr double kDeformed = 0.01;

// The largest |length - rest| / rest over the springs at `state`.
double largestStrain(const Body& body, const State& state);
// kLargeMotionStableFraction for a lightly damped world starting deformed, kStableFraction
// otherwise (for the course cube a lattice eigensolve the first time, then microseconds; for
// another body its modes at rest: `rest` when the caller has them, else computed).
double stableFraction(const World& world, const State& initial,
                      const Linearisation* rest = nullptr);

// The limit that matters when a run has diverged: the smaller of the limits at the initial
// state and with a face on a wall (two linearisations, about 0.3 s). NaN when the forces'
// derivatives there are not finite (no analysis is run then).
double predictedLimit(const World& world, const State& initial, Integrator integrator);

// The largest dt at which real runs of `time` seconds from `start` stay plausible (the checks of
// every Simulation, simulation.h), by bisection to 0.5% between a third and three times `guess`;
// NaN when the limit is not in that range, or when runs at guess / 3 would take more than
// kMaxSteps.
double observedLimit(const Model& model, const State& start, Integrator integrator, double time,
                     double guess);

// "%.3g" of x, "unbounded" for an infinity: how --check and the guard's advice write a figure.
std::string figureText(double x);

}  // namespace jello
