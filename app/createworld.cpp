// app/createworld.cpp: the createWorld command (createworld.h): a world from a recipe
// (app/worldbuilder.h) and the options (createworldoptions.h), so that a world is made without
// editing C.
//
//   createWorld [options] -o FILE     builds a world file
//   createWorld --describe WORLD      says what a world is

#include "app/createworld.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <new>
#include <string>
#include <utility>
#include <vector>

#include "analysis/stability.h"
#include "app/cli.h"
#include "app/createworldoptions.h"
#include "app/describe.h"
#include "app/worldbuilder.h"
#include "core/memory.h"
#include "core/output.h"
#include "io/input.h"
#include "io/scenereader.h"
#include "solver/physics.h"

namespace jello {

namespace {

Vec3 toVec3(const std::vector<double>& v) { return {v[0], v[1], v[2]}; }

void warn(const std::string& message) { jello::printError("warning: " + message); }

// The most field values the step's analysis copies (a 128^3 field, 50 MB): a larger field is
// left out of it (for R = 512, 7.5 GB).
constexpr std::size_t kMostAnalysedField = 3u * 128 * 128 * 128;

// Warnings for a world that will run, but perhaps not as its maker meant.
void warnAbout(jello::World& world, const jello::RunSettings& run, const jello::State& state) {
  jello::ForceField field;
  if (world.field.forces.size() > kMostAnalysedField)
    field = std::move(world.field), world.field = {};
  const std::string beyond = jello::beyondDoubles(world, state);
  if (!beyond.empty()) {
    warn("the world's numbers are beyond what double arithmetic can simulate (" + beyond +
         "): it will diverge at once");
  } else {
    // The step judged as jello --check judges it: the limit at rest or at the initial state,
    // whichever is smaller, and the same verdict.
    const jello::StabilityReport report = jello::analyseStability(world, state);
    const double limit = report.verdictLimit(run.integrator);
    const jello::Verdict verdict = jello::verdictFor(run.dt, limit, report.stableFraction);
    if (verdict != jello::Verdict::Stable) {
      char text[240];
      std::snprintf(text, sizeof text,
                    verdict == jello::Verdict::Unstable
                        ? "dt=%g exceeds %s's stable limit %s s for this world: it will diverge; "
                        : "dt=%g is close to %s's stable limit %s s for this world (jello --check "
                          "calls it marginal); ",
                    run.dt, jello::integratorName(run.integrator), jello::limitText(limit).c_str());
      warn(text + jello::stepAdvice(limit, report.stableFraction));
    }
  }
  int outside = 0;
  for (int c = 0; c < jello::kNumCoords; ++c)
    if (std::fabs(state.p()[c]) > jello::kBoxHalfSize) ++outside;
  if (outside) warn("the cube starts partly outside the box [-2,2]^3: the walls will push it in");
  if (int across = jello::pointsAcrossPlane(jello::makeModel(world, state), state)) {
    warn("the cube starts across the inclined plane (" + std::to_string(across) +
         " points on the far side of its centroid's side): the plane will push them back");
  }
  if (!field.forces.empty()) world.field = std::move(field);
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
      names = {"--field-uniform", "--gravity", "--field-swirl", "--field-radial", "--field-expr"};
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

// A course world file; a scene is refused by name (read as a .w file it would fail on its first
// line, saying nothing of why).
jello::WorldFile readCourseWorld(const std::string& path) {
  if (jello::isSceneFile(path))
    throw jello::InputError(path +
                            ": a scene file; createWorld reads and writes course worlds (.w), "
                            "and jello runs scenes (docs/scenes.md)");
  return jello::readWorldFile(path);
}

// createWorld --describe WORLD.
jello::Outcome printDescription(const CreateWorldOptions& o) {
  jello::setWorldUse(jello::WorldUse::Run);  // describing makes a Model, as a run does
  if (!o.output.empty()) return jello::failed("--describe reads a world; it does not go with -o");
  jello::WorldFile file = readCourseWorld(o.describe);
  std::printf("%s\n%s", o.describe.c_str(), jello::describeWorld(file).c_str());
  return jello::succeeded();
}

// The world to change: the defaults, a --preset or a --from world.
jello::Recipe startingRecipe(const CreateWorldOptions& o) {
  jello::Recipe recipe = jello::defaultRecipe();
  if (*o.presetOption) recipe = jello::coursePreset(o.preset);
  if (*o.fromOption) {
    jello::WorldFile base = readCourseWorld(o.from);
    // The field is moved, never copied: createWorld holds one field at a time.
    recipe.field.source = jello::FieldRecipe::Source::Given;
    recipe.field.given = std::move(base.world.field);
    base.world.field = {};
    recipe.world = std::move(base.world);
    recipe.run = base.run;
    recipe.state.from = base.state;
  }
  return recipe;
}

// The Parameters options, applied to `w`.
jello::Outcome applyParameters(const CreateWorldOptions& o, jello::World& w,
                               jello::RunSettings& run) {
  if (*o.integratorOption && !jello::parseIntegratorName(o.integrator, &run.integrator)) {
    return jello::failed("--integrator: unknown integrator '" + o.integrator + "', expected " +
                         jello::integratorNameList());
  }
  if (*o.dtOption) run.dt = o.dt;
  if (*o.nOption) run.n = o.n;
  if (*o.kElasticOption) w.kElastic = o.kElastic;
  if (*o.dElasticOption) w.dElastic = o.dElastic;
  if (*o.kCollisionOption) w.kCollision = o.kCollision;
  if (*o.dCollisionOption) w.dCollision = o.dCollision;
  if (*o.massOption) w.mass = o.mass;
  if (*o.noPlaneOption) w.hasPlane = false;
  if (*o.planeOption) {
    const std::vector<double>& plane = o.plane;
    const jello::Plane asked{plane[0], plane[1], plane[2], plane[3]};
    if (!jello::hasNormal(asked))
      return jello::failed("--plane: the normal (a, b, c) must not be zero");
    w.hasPlane = true;
    w.plane = asked;
    if (std::string why = jello::planeProblem(w.plane); !why.empty())
      return jello::failed("--plane: " + why);
  }
  return jello::succeeded();
}

// The Force field options, applied to `field`; `mass` (kg, a point's) turns --gravity into a
// force.
jello::Outcome applyField(const CreateWorldOptions& o, double mass, jello::FieldRecipe& field) {
  using Source = jello::FieldRecipe::Source;
  bool newSource = false;
  for (CLI::Option* option : o.fieldSources) newSource = newSource || option->count() > 0;
  if (newSource && field.source == Source::Given) {
    field.resolution = kCourseResolution;  // a --from world's field is replaced,
    field.given = {};                      // and let go before another is read or built
  }
  if (*o.resolutionOption) {
    if (field.source == Source::Given && !newSource) {
      return jello::failed(
          "--field-resolution: say which field to sample (the field taken --from a world is kept "
          "as it is)");
    }
    field.resolution = o.resolution;
    if (field.source == Source::None)
      field.source = Source::Uniform;  // a zero field, as the course writes
  }
  if (*o.uniformOption) {
    field.source = Source::Uniform;
    field.uniform = toVec3(o.uniform);
  }
  if (*o.gravityOption) {
    field.source = Source::Uniform;
    field.uniform = mass * toVec3(o.gravity);
  }
  if (*o.swirlOption) {
    field.source = Source::Swirl;
    field.strength = o.swirl;
  }
  if (*o.radialOption) {
    field.source = Source::Radial;
    field.strength = o.radial;
  }
  if (*o.expressionOption) {
    field.source = Source::Expression;
    field.expression = o.expression;
  }
  if (*o.fieldFromOption) {
    field.source = Source::Given;
    field.given = readCourseWorld(o.fieldFrom).world.field;
  }
  return jello::succeeded();
}

// The Initial state options, applied to `state`.
void applyState(const CreateWorldOptions& o, jello::StateRecipe& state) {
  if (*o.sizeOption) state.cubeSize = o.cubeSize;
  if (*o.centerOption) state.center = toVec3(o.center);
  if (*o.rotateOption) state.rotateDegrees = toVec3(o.rotation);
  if (*o.velocityOption) state.velocity = toVec3(o.velocity);
  if (*o.spinOption) state.spin = toVec3(o.spin);
  if (*o.skewOption) state.skewCorner = toVec3(o.skew);
  state.insideOut = o.insideOut;
}

// The recipe's field, given or built.
jello::ForceField takeField(jello::FieldRecipe& field) {
  using Source = jello::FieldRecipe::Source;
  if (field.source == Source::Given) return std::move(field.given);
  // Refused before the field is built, not by std::bad_alloc while building it.
  if (field.source != Source::None && field.resolution > 0)
    jello::requireMemory(jello::worldMemoryNeed(field.resolution, jello::WorldUse::Create));
  return jello::buildField(field);
}

// A uniform force meant as an acceleration: --field-uniform 0 0 -9.8 pulls 9.8 N on each point
// of 2 g, 5000 m/s^2, and crushes the cube flat.
void warnAboutForceAsAcceleration(const CreateWorldOptions& o, double mass) {
  constexpr double kStandardGravity = 9.80665;  // m/s^2
  constexpr double kMostLikelyGs = 10;          // what a user asks of a field, at most
  if (!*o.uniformOption) return;
  const double acceleration = jello::length(toVec3(o.uniform)) / mass;
  if (!(acceleration > kMostLikelyGs * kStandardGravity)) return;
  char text[240];
  std::snprintf(text, sizeof text,
                "--field-uniform is a force on each point, in N: it gives each %.4g m/s^2 (%.0f g) "
                "at %.9g kg; for an acceleration such as gravity, use --gravity GX GY GZ (m/s^2)",
                acceleration, acceleration / kStandardGravity, mass);
  warn(text);
}

// Checks, writes and announces the world made.
jello::Outcome writeWorld(const CreateWorldOptions& o, const CLI::App& app, jello::World& w,
                          const jello::RunSettings& run, const jello::State& initial) {
  // What is written must read back: the reader's rules, applied to the values themselves.
  if (auto problem = jello::findWorldProblem(w, run, initial))
    return jello::failed(describeProblem(*problem, app));
  warnAbout(w, run, initial);
  warnAboutForceAsAcceleration(o, w.mass);
  try {
    jello::writeWorldFile(o.output, w, run, initial, o.force);
  } catch (const std::runtime_error& e) {
    return jello::failed(e.what());  // e.g. the file appeared since checkWritable looked
  }
  std::string fieldSummary = "no field";
  if (w.field.resolution > 0) {
    fieldSummary = std::string(jello::fieldKindName(jello::classifyField(w.field).kind)) +
                   " field (R=" + std::to_string(w.field.resolution) + ")";
  }
  std::printf("wrote %s: %s dt=%g, %s, %s\n", o.output.c_str(),
              jello::integratorName(run.integrator), run.dt, fieldSummary.c_str(),
              w.hasPlane ? "inclined plane" : "no plane");
  return jello::succeeded();
}

// createWorld -o FILE: the world the options say, written to FILE.
jello::Outcome createWorld(const CreateWorldOptions& o, const CLI::App& app) {
  if (o.output.empty())
    return jello::failed("say where to write the world: -o FILE (see createWorld --help)");
  // Checked before any work (a field to build, a world to read), so that the refusal comes first.
  const jello::WriteCheck writable =
      jello::checkWritable(o.output, o.force ? jello::Existing::Replace : jello::Existing::Refuse);
  if (!writable.writable())
    return jello::failed(o.output + ": " + writable.why +
                         (writable.alreadyExists ? "; add --force to replace it" : ""));

  jello::setWorldUse(jello::WorldUse::Create);
  jello::Recipe recipe = startingRecipe(o);
  if (jello::Outcome applied = applyParameters(o, recipe.world, recipe.run); !applied.ok())
    return applied;
  if (jello::Outcome applied = applyField(o, recipe.world.mass, recipe.field); !applied.ok())
    return applied;
  applyState(o, recipe.state);
  recipe.world.field = takeField(recipe.field);
  const jello::State initial = jello::buildState(recipe.state);
  return writeWorld(o, app, recipe.world, recipe.run, initial);
}

// What the command line asks, its errors as outcomes (exceptions included).
jello::Outcome run(const CreateWorldOptions& o, const CLI::App& app) {
  if (*o.maxMemoryOption)
    jello::setMemoryLimit(static_cast<std::uint64_t>(std::min(o.maxMemory * 1e9, 1e18)));
  try {
    return *o.describeOption ? printDescription(o) : createWorld(o, app);
  } catch (const jello::InputError& e) {
    return jello::failed(e.what());
  } catch (const jello::NotEnoughMemory& e) {
    return jello::failed(e.what());
  } catch (const std::bad_alloc&) {
    // The need was computed, but something else holds memory meanwhile.
    return jello::failed("not enough memory for this world (an allocation failed)");
  }
}

}  // namespace

Outcome createWorldCommand(int argc, const char* const* argv) {
  CLI::App app{
      "createWorld: builds a jello world file (docs/world-format.md). Start from the defaults (the "
      "course's springs, a cube on [0,1]^3 at rest, no plane, no field), a --preset or a world "
      "--from, then change what the options say.",
      "createWorld"};
  CreateWorldOptions options;
  addCreateWorldOptions(app, options);
  const Outcome parsed = parseCommandLine(app, argc, argv);
  if (!parsed.ok()) return parsed;
  if (parsed.message == kAnswered) return succeeded();
  return run(options, app);
}

}  // namespace jello
