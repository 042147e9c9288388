// createWorld.cpp: a command-line world builder, so that a world is made without editing C.
//
//   createWorld [options] -o FILE     builds a world file
//   createWorld --describe WORLD      says what a world is

#include <limits.h>
#include <sys/stat.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <new>
#include <string>
#include <utility>
#include <vector>

#include "cli.h"
#include "describe.h"
#include "output.h"
#include "memory.h"
#include "physics.h"
#include "stability.h"
#include "worldbuilder.h"

namespace {

using jello::kFinite;
using jello::kNonNegative;
using jello::kPositive;
using jello::Vec3;

constexpr int kExitOk = 0;
constexpr int kExitBadInput = 2;
constexpr const char* kVersion = "createWorld 0.1.0";

Vec3 toVec3(const std::vector<double>& v) { return {v[0], v[1], v[2]}; }

int fail(const std::string& message) {
  jello::printError(message);
  return kExitBadInput;
}

void warn(const std::string& message) { jello::printError("warning: " + message); }

// Warnings for a world that will run, but perhaps not as its maker meant.
void warnAbout(jello::World& world, const jello::State& state) {
  // Nothing here looks at the field: it is set aside, so that the Model below copies none of it
  // (for R = 512, 7.5 GB).
  jello::ForceField field = std::move(world.field);
  world.field = {};
  const std::string beyond = jello::beyondDoubles(world, state);
  const double limit = jello::criticalStep(world.integrator, jello::lineariseAtRest(world).modes);
  if (!beyond.empty()) {
    warn("the world's numbers are beyond what double arithmetic can simulate (" + beyond +
         "): it will diverge at once");
  } else if (world.dt > limit) {
    char text[200];
    std::snprintf(
        text, sizeof text, "dt=%g exceeds %s's stable limit %s s for this world: it will diverge; ",
        world.dt, jello::integratorName(world.integrator), jello::limitText(limit).c_str());
    warn(text + jello::stepAdvice(limit));
  }
  int outside = 0;
  for (int c = 0; c < jello::kNumCoords; ++c)
    if (std::fabs(state.p()[c]) > jello::kBoxHalfSize) ++outside;
  if (outside) warn("the cube starts partly outside the box [-2,2]^3: the walls will push it in");
  if (int across = jello::pointsAcrossPlane(jello::makeModel(world, state), state)) {
    warn("the cube starts across the inclined plane (" + std::to_string(across) +
         " points on the far side of its centroid's side): the plane will push them back");
  }
  world.field = std::move(field);
}


// The options given that shape `part` of a world, in the order of --help: what a message about
// that part names. A --preset or a --from world is valid by itself, so neither is named.
std::vector<std::string> optionsShaping(jello::WorldProblem::Part part, const CLI::App& app) {
  using Part = jello::WorldProblem::Part;
  std::vector<const char*> names;
  switch (part) {
    case Part::Parameters:
      names = {"--dt",          "--n",           "--k-elastic", "--d-elastic",
               "--k-collision", "--d-collision", "--mass"};
      break;
    case Part::Plane:
      names = {"--plane"};
      break;
    case Part::Field:
      names = {"--field-uniform", "--field-swirl", "--field-radial", "--field-expr"};
      break;
    case Part::Position:
      names = {"--cube-size", "--center", "--rotate", "--skew-corner"};
      break;
    case Part::Velocity:
      names = {"--rotate", "--velocity", "--spin"};
      break;
  }
  std::vector<std::string> given;
  for (const char* name : names)
    if (app.get_option(name)->count() > 0) given.push_back(name);
  return given;
}

// One line on what makes the world invalid, in the terms of the options that made it: never a
// line number of a text that is not written.
std::string describeProblem(const jello::WorldProblem& problem, const CLI::App& app) {
  std::vector<std::string> options = optionsShaping(problem.part, app);
  if (options.size() == 1) return options[0] + ": " + problem.what;
  std::string from;
  for (const std::string& option : options) from += (from.empty() ? " (from " : ", ") + option;
  return "the world would be invalid: " + problem.what + (from.empty() ? "" : from + ")");
}

}  // namespace

static int createWorld(int argc, char** argv) {
  CLI::App app{
      "createWorld: builds a jello world file (SPEC section 1). Start from the defaults (the course's "
      "springs, a cube on [0,1]^3 at rest, no plane, no field), a --preset or a world --from, then change "
      "what the options say.",
      "createWorld"};
  app.set_version_flag("--version", kVersion);

  std::string output, describe, preset, from;
  bool force = false;
  app.add_option("-o,--output", output, "the world file to write")->type_name("FILE");
  auto* describeOption = app.add_option("--describe", describe, "print what WORLD is, and exit")->type_name("WORLD");
  app.add_flag("--force", force, "replace FILE when it exists");
  double maxMemory = 0;
  auto* maxMemoryOption =
      app.add_option(
             "--max-memory", maxMemory,
             "memory the world may take, GB (default: what the machine and its limits allow)")
          ->type_name("GB")
          ->check(kPositive);
  auto* presetOption = app.add_option("--preset", preset, "start from a course world")->type_name("NAME")
                           ->check(CLI::IsMember({"jello", "rotate", "moveLeft", "skewedCorner", "gravity"}));
  auto* fromOption = app.add_option("--from", from, "start from WORLD: its state, and every parameter not given")->type_name("WORLD");
  presetOption->excludes(fromOption);

  std::string integrator;
  double dt = 0, kElastic = 0, dElastic = 0, kCollision = 0, dCollision = 0, mass = 0;
  int n = 0;
  std::vector<double> plane;
  auto* integratorOption = app.add_option("--integrator", integrator, jello::integratorNameList() + ", any case")->type_name("NAME")->group("Parameters");
  auto* dtOption = app.add_option("--dt", dt, "time step, s")->type_name("DT")->transform(kPositive)->group("Parameters");
  auto* nOption = app.add_option("--n", n, "steps per drawn frame")->type_name("N")
                      ->transform(jello::wholeNumber(1, std::numeric_limits<int>::max()))
                      ->group("Parameters");
  auto* kElasticOption = app.add_option("--k-elastic", kElastic, "spring stiffness, N/m")->type_name("K")->transform(kNonNegative)->group("Parameters");
  auto* dElasticOption = app.add_option("--d-elastic", dElastic, "spring damping, N s/m")->type_name("D")->transform(kNonNegative)->group("Parameters");
  auto* kCollisionOption =
      app.add_option("--k-collision", kCollision, "collision stiffness, N/m")->type_name("K")->transform(kNonNegative)->group("Parameters");
  auto* dCollisionOption =
      app.add_option("--d-collision", dCollision, "collision damping, N s/m")->type_name("D")->transform(kNonNegative)->group("Parameters");
  auto* massOption = app.add_option("--mass", mass, "mass of each of the 512 points, kg")->type_name("KG")->transform(kPositive)->group("Parameters");
  auto* planeOption = app.add_option("--plane", plane, "inclined plane a x + b y + c z + d = 0")->type_name("A B C D")
                          ->expected(4)
                          ->transform(kFinite)
                          ->group("Parameters");
  auto* noPlaneOption = app.add_flag("--no-plane", "no inclined plane")->group("Parameters");
  planeOption->excludes(noPlaneOption);

  int resolution = 0;
  std::vector<double> uniform;
  double swirl = 0, radial = 0;
  std::string expression, fieldFrom;
  auto* resolutionOption = app.add_option("--field-resolution", resolution, "field grid R (R^3 nodes; 0: no field)")->type_name("R")
                               ->transform(jello::wholeNumber(0, jello::kMaxResolution))
                               ->group("Force field");
  auto* uniformOption =
      app.add_option("--field-uniform", uniform, "uniform force FX FY FZ, N")->type_name("FX FY FZ")->expected(3)->transform(kFinite)->group("Force field");
  auto* swirlOption =
      app.add_option("--field-swirl", swirl, "swirl about z: F = S (-y, x, 0)")->type_name("S")->transform(kFinite)->group("Force field");
  auto* radialOption =
      app.add_option("--field-radial", radial, "radial: F = S (x, y, z)")->type_name("S")->transform(kFinite)->group("Force field");
  auto* expressionOption =
      app.add_option("--field-expr", expression, "\"fx; fy; fz\" in x, y, z (muparser syntax), N")->type_name("'FX; FY; FZ'")->group("Force field");
  auto* fieldFromOption = app.add_option("--field-from", fieldFrom, "copy the field of WORLD")->type_name("WORLD")->group("Force field");
  std::vector<CLI::Option*> fieldSources = {uniformOption, swirlOption, radialOption, expressionOption, fieldFromOption};
  for (CLI::Option* a : fieldSources)
    for (CLI::Option* b : fieldSources)
      if (a != b) a->excludes(b);
  fieldFromOption->excludes(resolutionOption);

  double cubeSize = 1;
  std::vector<double> center, rotation, velocity, spin, skew;
  auto* sizeOption = app.add_option("--cube-size", cubeSize, "edge of the cube at rest, m (default 1)")->type_name("L")
                         ->transform(kPositive)
                         ->group("Initial state");
  auto* centerOption = app.add_option("--center", center, "centre of the cube X Y Z, m (default: corner at the origin)")->type_name("X Y Z")
                           ->expected(3)
                           ->transform(kFinite)
                           ->group("Initial state");
  auto* rotateOption = app.add_option("--rotate", rotation, "turn the cube about x, then y, then z, degrees")->type_name("AX AY AZ")
                           ->expected(3)
                           ->transform(kFinite)
                           ->group("Initial state");
  auto* velocityOption = app.add_option("--velocity", velocity, "velocity of every point VX VY VZ, m/s")->type_name("VX VY VZ")
                             ->expected(3)
                             ->transform(kFinite)
                             ->group("Initial state");
  auto* spinOption = app.add_option("--spin", spin, "rigid angular velocity WX WY WZ about the centre, rad/s")->type_name("WX WY WZ")
                         ->expected(3)
                         ->transform(kFinite)
                         ->group("Initial state");
  auto* skewOption = app.add_option("--skew-corner", skew, "displace corner p[7][7][7] by DX DY DZ, m")->type_name("DX DY DZ")
                         ->expected(3)
                         ->transform(kFinite)
                         ->group("Initial state");
  bool insideOut = false;
  app.add_flag("--inside-out", insideOut, "reflect the cube through its centre: every face faces in")->group("Initial state");
  sizeOption->excludes(fromOption);

  int status = 0;
  if (!jello::parseCommandLine(app, argc, argv, &status)) return status;

  if (*maxMemoryOption)
    jello::setMemoryLimit(static_cast<std::uint64_t>(std::min(maxMemory * 1e9, 1e18)));
  try {
    if (*describeOption) {
      jello::setWorldUse(jello::WorldUse::Run);  // describing makes a Model, as a run does
      if (!output.empty()) return fail("--describe reads a world; it does not go with -o");
      jello::WorldFile file = jello::readWorldFile(describe);
      std::printf("%s\n%s", describe.c_str(), jello::describeWorld(file.world, file.state).c_str());
      return kExitOk;
    }
    if (output.empty()) return fail("say where to write the world: -o FILE (see createWorld --help)");
    // Checked before any work (a field to build, a world to read), so that the refusal comes first.
    if (std::string why = jello::whyNotWritable(output, force ? jello::Existing::Replace : jello::Existing::Refuse);
        !why.empty())
      return fail(output + ": " + why + (why == "already exists" ? "; add --force to replace it" : ""));

    jello::setWorldUse(jello::WorldUse::Create);
    jello::Recipe recipe = jello::defaultRecipe();
    if (*presetOption) recipe = jello::coursePreset(preset);
    if (*fromOption) {
      jello::WorldFile base = jello::readWorldFile(from);
      // The field is moved, never copied: createWorld holds one field at a time.
      recipe.field.source = jello::FieldRecipe::Source::Given;
      recipe.field.given = std::move(base.world.field);
      base.world.field = {};
      recipe.world = std::move(base.world);
      recipe.state.from = base.state;
    }

    jello::World& w = recipe.world;
    if (*integratorOption && !jello::parseIntegratorName(integrator, &w.integrator)) {
      return fail("--integrator: unknown integrator '" + integrator + "', expected " + jello::integratorNameList());
    }
    if (*dtOption) w.dt = dt;
    if (*nOption) w.n = n;
    if (*kElasticOption) w.kElastic = kElastic;
    if (*dElasticOption) w.dElastic = dElastic;
    if (*kCollisionOption) w.kCollision = kCollision;
    if (*dCollisionOption) w.dCollision = dCollision;
    if (*massOption) w.mass = mass;
    if (*noPlaneOption) w.hasPlane = false;
    if (*planeOption) {
      if (plane[0] == 0 && plane[1] == 0 && plane[2] == 0) return fail("--plane: the normal (a, b, c) must not be zero");
      w.hasPlane = true;
      w.plane = {plane[0], plane[1], plane[2], plane[3]};
      if (std::string why = jello::planeProblem(w.plane); !why.empty())
        return fail("--plane: " + why);
    }

    using Source = jello::FieldRecipe::Source;
    jello::FieldRecipe& field = recipe.field;
    bool newSource = false;
    for (CLI::Option* option : fieldSources) newSource = newSource || option->count() > 0;
    if (newSource && field.source == Source::Given) {
      field.resolution = 30;  // a --from world's field is replaced,
      field.given = {};       // and let go before another is read or built
    }
    if (*resolutionOption) {
      if (field.source == Source::Given && !newSource) {
        return fail("--field-resolution: say which field to sample (the field taken --from a world is kept as it is)");
      }
      field.resolution = resolution;
      if (field.source == Source::None) field.source = Source::Uniform;  // a zero field, as the course writes
    }
    if (*uniformOption) {
      field.source = Source::Uniform;
      field.uniform = toVec3(uniform);
    }
    if (*swirlOption) {
      field.source = Source::Swirl;
      field.strength = swirl;
    }
    if (*radialOption) {
      field.source = Source::Radial;
      field.strength = radial;
    }
    if (*expressionOption) {
      field.source = Source::Expression;
      field.expression = expression;
    }
    if (*fieldFromOption) {
      field.source = Source::Given;
      field.given = jello::readWorldFile(fieldFrom).world.field;
    }

    jello::StateRecipe& state = recipe.state;
    if (*sizeOption) state.cubeSize = cubeSize;
    if (*centerOption) state.center = toVec3(center);
    if (*rotateOption) state.rotateDegrees = toVec3(rotation);
    if (*velocityOption) state.velocity = toVec3(velocity);
    if (*spinOption) state.spin = toVec3(spin);
    if (*skewOption) state.skewCorner = toVec3(skew);
    state.insideOut = insideOut;

    if (field.source == Source::Given) {
      w.field = std::move(field.given);
    } else {
      // Refused before the field is built, not by std::bad_alloc while building it.
      if (field.source != Source::None && field.resolution > 0)
        jello::requireMemory(jello::worldMemoryNeed(field.resolution, jello::WorldUse::Create));
      w.field = jello::buildField(field);
    }
    jello::State initial = jello::buildState(state);

    // What is written must read back: the reader's rules, applied to the values themselves.
    if (auto problem = jello::findWorldProblem(w, initial))
      return fail(describeProblem(*problem, app));
    warnAbout(w, initial);
    try {
      jello::writeWorldFile(output, w, initial, force);
    } catch (const std::runtime_error& e) {
      return fail(e.what());  // e.g. the file appeared since whyNotWritable looked
    }
    std::string fieldSummary = "no field";
    if (w.field.resolution > 0) {
      fieldSummary = std::string(jello::fieldKindName(jello::classifyField(w.field).kind)) + " field (R=" +
                     std::to_string(w.field.resolution) + ")";
    }
    std::printf("wrote %s: %s dt=%g, %s, %s\n", output.c_str(), jello::integratorName(w.integrator), w.dt,
                fieldSummary.c_str(), w.hasPlane ? "inclined plane" : "no plane");
    return kExitOk;
  } catch (const jello::WorldFileError& e) {
    return fail(e.what());
  } catch (const jello::RecipeError& e) {
    return fail(e.what());
  } catch (const jello::NotEnoughMemory& e) {
    return fail(e.what());
  } catch (const std::bad_alloc&) {
    // The need was computed, but something else holds memory meanwhile.
    return fail("not enough memory for this world (an allocation failed)");
  }
}

// Every exception ends here as one line and exit status 2.
int main(int argc, char** argv) {
  jello::setProgramName("createWorld");
  jello::installSignalCleanup();
  try {
    return createWorld(argc, argv);
  } catch (const std::bad_alloc&) {
    return fail("not enough memory for this world");
  } catch (const std::exception& e) {
    return fail(e.what());
  }
}
