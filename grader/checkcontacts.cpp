// checkcontacts.cpp: the walls, the plane and the field, each isolated by moving the cube
// rigidly (its springs stay as they were, so only the contact changes) or by swapping the field.
#include <algorithm>
#include <cmath>

#include "grader/checkkit.h"
#include "solver/physics.h"

namespace jello::grader {
namespace {

constexpr double kExact = 1e-8;
constexpr double kNoForce = 1e-7;  // N

// A contact measured on the points across it: the cube moved across by depth1 and depth2 from a
// place just inside, then at depth2 moving with `velocity`.
struct ContactProbe {
  State inside;
  Vec3 inward;  // unit normal into the allowed region
  double depth1 = 0.01, depth2 = 0.02;
  Vec3 velocity;  // into the contact and along it
};

void scriptContact(Script& script, const ContactProbe& probe) {
  auto moved = [&](double depth, Vec3 v) {
    State s = probe.inside;
    for (int q = 0; q < kNumPoints; ++q) {
      store(s.p(), q, load(s.p(), q) - (depth + 0.01) * probe.inward);
      store(s.v(), q, v);
    }
    return s;
  };
  for (State s : {probe.inside, moved(probe.depth1, {}), moved(probe.depth2, {}),
                  moved(probe.depth2, probe.velocity)}) {
    script.state(s);
    script.accelerations();
  }
}

// Judges the answers [first, first + 4) of a contact probe: `across` says which points are
// across at both depths. "" when right.
std::string judgeContact(const ProbeRun& run, std::size_t first, const ContactProbe& probe,
                         const std::vector<bool>& across, const World& world,
                         const std::string& name) {
  const auto& a = run.answers;
  for (int n = 0; n < 4; ++n) {
    if (!allUsable(a[first + n])) return name + ": NaN or infinity in the accelerations";
  }
  for (int q = 0; q < kNumPoints; ++q) {
    if (across[q]) continue;
    for (int n = 1; n < 4; ++n) {
      if (length(forceChange(a[first + n], a[first], q)) > kNoForce) {
        return name + ": pushes " + pointName(q) + ", which is not across it";
      }
    }
  }
  int count = 0;
  for (int q = 0; q < kNumPoints; ++q) {
    if (!across[q]) continue;
    Vec3 f1 = forceChange(a[first + 1], a[first], q), f2 = forceChange(a[first + 2], a[first], q);
    Vec3 damp = forceChange(a[first + 3], a[first + 2], q);
    ++count;
    double n1 = dot(f1, probe.inward), n2 = dot(f2, probe.inward);
    if (std::fabs(n2) < kNoForce) return name + ": no force on points across it";
    double k = (n2 - n1) / (probe.depth2 - probe.depth1), rest = probe.depth1 - n1 / k;
    // Every comparison is written to fail on a NaN.
    if (!(length(f2 - n2 * probe.inward) <= kNoForce))
      return name + ": the force is not along the normal";
    if (!(std::fabs(k - world.kCollision) <= kExact * world.kCollision)) {
      return name +
             textf(": stiffness %.6g N/m measured, kCollision = %g N/m expected%s", k,
                   world.kCollision, k < 0 ? " (it pulls points further across)" : "") +
             massHint(k, world.kCollision);
    }
    if (!(std::fabs(rest) <= 1e-9))
      return name + textf(": rest length %.3g m measured, 0 expected", rest);
    Vec3 into = dot(probe.velocity, probe.inward) * probe.inward;
    Vec3 expected = -world.dCollision * into;  // -d (v . u) u, u out of the allowed side
    if (!(length(damp - expected) <= kExact * length(expected))) {
      if (length(damp) < kNoForce) return name + ": no damping";
      if (length(damp + expected) < kExact * length(expected))
        return name + ": damping sign flipped";
      if (length(damp - (-world.dCollision) * probe.velocity) < kExact * length(expected)) {
        return name + ": damps the velocity along the contact too, not only into it";
      }
      return name +
             textf(": damping force %.6g N, %.6g N expected", length(damp), length(expected)) +
             massHint(length(damp), length(expected));
    }
  }
  return count == 0 ? name + ": nothing crossed it (grader error)" : "";
}

std::vector<bool> acrossWall(const State& s, int axis, double side) {
  std::vector<bool> across(kNumPoints);
  for (int q = 0; q < kNumPoints; ++q) across[q] = s.p()[coordIndex(q, axis)] * side > 1.98;
  return across;
}

const char* const kWallNames[6] = {"wall x = -2", "wall x = +2", "wall y = -2",
                                   "wall y = +2", "wall z = -2", "wall z = +2"};

// This project's force (N) on each point of `state` in `world` (physics.md).
std::vector<double> projectForces(const World& world, const State& state) {
  Model model = makeModel(world, state);
  std::vector<double> force(kNumCoords);
  computeForces(model, state.p(), state.v(), force.data());
  return force;
}

// A point across two walls (an edge) or three (a corner), as the course's worlds have when a
// cube lands on an edge: each wall pushes and damps on its own (physics.md), not one spring to
// the box's edge. The cube moved rigidly 1.5 cm across the walls named, moving into them: its
// force change against the cube just inside, compared with this project's. "" when right.
std::string judgeEdges(const std::string& probe, const World& world) {
  struct Edge {
    const char* name;
    Vec3 out;  // the walls crossed: +1 or -1 on each axis crossed, 0 on the others
  };
  const Edge edges[] = {{"the edge of walls x = +2 and y = +2", {1, 1, 0}},
                        {"the corner of walls x = -2, y = +2 and z = -2", {-1, 1, -1}}};
  for (const Edge& edge : edges) {
    State inside = restLattice(kCentred + 1.49 * edge.out), across = inside;
    for (int q = 0; q < kNumPoints; ++q) {
      store(across.p(), q, load(inside.p(), q) + 0.025 * edge.out);
      store(across.v(), q, 0.4 * edge.out + Vec3{0.1, 0.2, 0.3});
    }
    std::string failure;
    auto answers = accelerationsAt(probe, world, {inside, across}, &failure);
    if (!failure.empty()) return failure + " at " + edge.name;
    std::vector<double> expected = projectForces(world, across),
                        before = projectForces(world, inside);
    for (int q = 0; q < kNumPoints; ++q) {
      Vec3 want = load(expected.data(), q) - load(before.data(), q);
      Vec3 got = forceChange(answers[1], answers[0], q);
      if (!(length(got - want) <= kExact * std::max(1.0, length(want)))) {
        return textf(
            "at %s (points across both or all three): the force on %s is (%.6g, %.6g, "
            "%.6g) N, (%.6g, %.6g, %.6g) N expected: each wall pushes and damps on its "
            "own, along its own normal",
            edge.name, pointName(q).c_str(), got.x, got.y, got.z, want.x, want.y, want.z);
      }
    }
  }
  return "";
}

}  // namespace

CheckResult checkWalls(const std::string& probe) {
  World world = probeWorld();
  Script script;
  script.world(world, probeRun(), restLattice(kCentred));
  std::vector<ContactProbe> probes;
  for (int wall = 0; wall < 6; ++wall) {
    int axis = wall / 2;
    double side = wall % 2 ? 1 : -1;
    Vec3 outward = {axis == 0 ? side : 0, axis == 1 ? side : 0, axis == 2 ? side : 0};
    Vec3 along = {axis == 1 ? 0.3 : 0, axis == 2 ? 0.3 : 0, axis == 0 ? 0.3 : 0};
    // Its face 0.01 m inside the wall.
    ContactProbe p{restLattice(kCentred + 1.49 * outward), -outward, 0.01, 0.02,
                   0.4 * outward + along};
    scriptContact(script, p);
    probes.push_back(p);
  }
  ProbeRun run = runProbe(probe, script);
  if (!run.complete()) return crashed("walls", run, "with the cube against a wall");
  // Every wall is judged: walls that fail alike are named together ("walls x = +2, y = +2: no
  // force on points across them"), the first finding first.
  std::vector<std::pair<std::string, std::string>> findings;  // what is wrong, which walls
  for (int wall = 0; wall < 6; ++wall) {
    std::vector<bool> across = acrossWall(probes[wall].inside, wall / 2, wall % 2 ? 1 : -1);
    std::string name = kWallNames[wall];
    std::string why = judgeContact(run, 4 * wall, probes[wall], across, world, name);
    if (why.empty()) continue;
    std::string what = why.substr(name.size() + 2);
    auto same = std::find_if(findings.begin(), findings.end(),
                             [&](const auto& finding) { return finding.first == what; });
    if (same == findings.end())
      findings.emplace_back(what, name);
    else
      same->second += ", " + name.substr(5);  // "wall x = -2" -> "x = -2"
  }
  if (findings.empty()) {
    std::string edges = judgeEdges(probe, world);
    if (!edges.empty()) return failed("walls", edges);
    return passed("walls",
                  "all six: kCollision, rest length 0, only beyond the wall, damping into it; "
                  "an edge and a corner, each wall on its own");
  }
  std::string line;
  for (const auto& [what, walls] : findings) {
    bool several = walls.find(',') != std::string::npos;
    bool all = std::count(walls.begin(), walls.end(), ',') == 5;
    line += (line.empty() ? "" : "; ") +
            (all       ? std::string("all six walls")
             : several ? "walls " + walls.substr(5)
                       : walls) +
            ": " + what;
  }
  return failed("walls", line);
}

CheckResult checkPlane(const std::string& probe) {
  World world = probeWorld();
  // The plane x + y + 2z + d = 0, not normalised as in the course's worlds, 0.01 m under the
  // cube's corner p[0][0][0]: the cube is on its positive side (the course's convention).
  Vec3 a = {1, 1, 2};
  double norm = length(a);
  State inside = restLattice(kCentred);
  world.hasPlane = true;
  world.plane = {a.x, a.y, a.z, -dot(a, load(inside.p(), 0)) + 0.01 * norm};
  Vec3 inward = (1 / norm) * a;
  Vec3 along = (1 / std::sqrt(2.0)) * Vec3{1, -1, 0};
  ContactProbe p{inside, inward, 0.01, 0.02, -0.4 * inward + 0.3 * along};
  Script script;
  script.world(world, probeRun(), inside);
  scriptContact(script, p);
  // The same states without the plane: the difference is the plane's force alone, whatever else
  // the submission's own terms do where the cube is (an obstacle of its own).
  World without = world;
  without.hasPlane = false;
  script.world(without, probeRun(), inside);
  scriptContact(script, p);
  // The same cube with the plane's coefficients negated: on the negative side (not graded).
  World negated = world;
  negated.plane = {-a.x, -a.y, -a.z, -world.plane.d};
  script.world(negated, probeRun(), inside);
  script.accelerations();
  ProbeRun run = runProbe(probe, script);
  if (run.answers.size() < 8) return crashed("plane", run, "with a corner across the plane");
  ProbeRun plane = run;  // its answers: with the plane less without it, the inside state's kept
  plane.answers.resize(4);
  for (std::size_t n = 0; n < 4; ++n) {
    for (std::size_t c = 0; c < plane.answers[n].size(); ++c)
      plane.answers[n][c] = run.answers[n][c] - run.answers[4 + n][c] + run.answers[4][c];
  }
  std::vector<bool> across(kNumPoints, false);
  across[0] = true;
  std::string why = judgeContact(plane, 0, p, across, world, "plane");
  CheckResult result = why.empty() ? passed("plane",
                                            "kCollision, rest length 0, the positive side, "
                                            "damping into it")
                                   : failed("plane", why);
  if (why.find("which is not across it") != std::string::npos) {
    result.diagnosis =
        "plane: pushes points on its positive side, where the cube is: the allowed "
        "side is the wrong one";
  }
  if (run.complete() && length(forceChange(run.answers[8], run.answers[0], 1)) > kNoForce) {
    result.notes.push_back(
        "information, not a fault: it keeps the course's convention, points on the plane's "
        "positive side, as every course world starts them (with the plane's coefficients negated "
        "it pushes the cube back to that side); this project keeps whichever side the cube starts "
        "on, which differs only for a cube that starts on the negative side");
  }
  return result;
}

}  // namespace jello::grader
