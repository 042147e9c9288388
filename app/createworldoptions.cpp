// app/createworldoptions.cpp: createWorld's options (createworldoptions.h), their checks and help.

#include "app/createworldoptions.h"

#include <string>
#include <vector>

#include "app/cli.h"
#include "app/worldbuilder.h"
#include "model/integrator.h"
#include "model/world.h"

namespace jello {

namespace {

constexpr const char* kVersion = "createWorld 0.1.0";

// --preset's choices: the preset table's names.
std::vector<std::string> presetNames() {
  std::vector<std::string> names;
  for (const Preset& preset : coursePresets()) names.push_back(preset.name);
  return names;
}

void addGeneralOptions(CLI::App& app, CreateWorldOptions& o) {
  app.set_version_flag("--version", kVersion);
  app.add_option("-o,--output", o.output, "the world file to write")->type_name("FILE");
  o.describeOption =
      app.add_option("--describe", o.describe, "print what WORLD is, and exit")->type_name("WORLD");
  app.add_flag("--force", o.force, "replace FILE when it exists");
  o.maxMemoryOption =
      app.add_option(
             "--max-memory", o.maxMemory,
             "memory the world may take, GB (default: what the machine and its limits allow)")
          ->type_name("GB")
          ->check(kPositive);
  o.presetOption = app.add_option("--preset", o.preset, "start from a course world")
                       ->type_name("NAME")
                       ->check(CLI::IsMember(presetNames()));
  o.fromOption =
      app.add_option("--from", o.from, "start from WORLD: its state, and every parameter not given")
          ->type_name("WORLD");
  o.presetOption->excludes(o.fromOption);
}

void addParameterOptions(CLI::App& app, CreateWorldOptions& o) {
  o.integratorOption =
      app.add_option("--integrator", o.integrator, jello::integratorNameList() + ", any case")
          ->type_name("NAME")
          ->group("Parameters");
  o.dtOption = app.add_option("--dt", o.dt, "time step, s")
                   ->type_name("DT")
                   ->transform(kPositive)
                   ->group("Parameters");
  o.nOption = app.add_option("--n", o.n, "steps per drawn frame")
                  ->type_name("N")
                  ->transform(jello::wholeNumber(1, kMostStepsPerFrame))
                  ->group("Parameters");
  o.kElasticOption = app.add_option("--k-elastic", o.kElastic, "spring stiffness, N/m")
                         ->type_name("K")
                         ->transform(kNonNegative)
                         ->group("Parameters");
  o.dElasticOption = app.add_option("--d-elastic", o.dElastic, "spring damping, N s/m")
                         ->type_name("D")
                         ->transform(kNonNegative)
                         ->group("Parameters");
  o.kCollisionOption = app.add_option("--k-collision", o.kCollision, "collision stiffness, N/m")
                           ->type_name("K")
                           ->transform(kNonNegative)
                           ->group("Parameters");
  o.dCollisionOption = app.add_option("--d-collision", o.dCollision, "collision damping, N s/m")
                           ->type_name("D")
                           ->transform(kNonNegative)
                           ->group("Parameters");
  o.massOption = app.add_option("--mass", o.mass, "mass of each of the 512 points, kg")
                     ->type_name("KG")
                     ->transform(kPositive)
                     ->group("Parameters");
  o.planeOption = app.add_option("--plane", o.plane, "inclined plane a x + b y + c z + d = 0")
                      ->type_name("A B C D")
                      ->expected(4)
                      ->transform(kFinite)
                      ->group("Parameters");
  o.noPlaneOption = app.add_flag("--no-plane", "no inclined plane")->group("Parameters");
  o.planeOption->excludes(o.noPlaneOption);
}

void addFieldOptions(CLI::App& app, CreateWorldOptions& o) {
  o.resolutionOption =
      app.add_option("--field-resolution", o.resolution, "field grid R (R^3 nodes; 0: no field)")
          ->type_name("R")
          ->transform(jello::wholeNumber(0, jello::kMaxResolution))
          ->group("Force field");
  o.uniformOption = app.add_option("--field-uniform", o.uniform, "uniform force FX FY FZ, N")
                        ->type_name("FX FY FZ")
                        ->expected(3)
                        ->transform(kFinite)
                        ->group("Force field");
  o.gravityOption =
      app.add_option("--gravity", o.gravity,
                     "uniform acceleration GX GY GZ, m/s^2 (e.g. 0 0 -9.8): written as the "
                     "uniform force mass x g")
          ->type_name("GX GY GZ")
          ->expected(3)
          ->transform(kFinite)
          ->group("Force field");
  o.swirlOption = app.add_option("--field-swirl", o.swirl, "swirl about z: F = S (-y, x, 0)")
                      ->type_name("S")
                      ->transform(kFinite)
                      ->group("Force field");
  o.radialOption = app.add_option("--field-radial", o.radial, "radial: F = S (x, y, z)")
                       ->type_name("S")
                       ->transform(kFinite)
                       ->group("Force field");
  o.expressionOption =
      app.add_option("--field-expr", o.expression, "\"fx; fy; fz\" in x, y, z (muparser syntax), N")
          ->type_name("'FX; FY; FZ'")
          ->group("Force field");
  o.fieldFromOption = app.add_option("--field-from", o.fieldFrom, "copy the field of WORLD")
                          ->type_name("WORLD")
                          ->group("Force field");
  o.fieldSources = {o.uniformOption, o.gravityOption,    o.swirlOption,
                    o.radialOption,  o.expressionOption, o.fieldFromOption};
  for (CLI::Option* a : o.fieldSources)
    for (CLI::Option* b : o.fieldSources)
      if (a != b) a->excludes(b);
  o.fieldFromOption->excludes(o.resolutionOption);
}

void addStateOptions(CLI::App& app, CreateWorldOptions& o) {
  o.sizeOption =
      app.add_option("--cube-size", o.cubeSize, "edge of the cube at rest, m (default 1)")
          ->type_name("L")
          ->transform(kPositive)
          ->group("Initial state");
  // The five vector options of the initial state: three finite numbers each.
  auto vector = [&app](const char* name, std::vector<double>& target, const char* help,
                       const char* names) {
    return app.add_option(name, target, help)
        ->type_name(names)
        ->expected(3)
        ->transform(kFinite)
        ->group("Initial state");
  };
  o.centerOption = vector("--center", o.center,
                          "centre of the cube X Y Z, m (default: corner at the origin)", "X Y Z");
  o.rotateOption =
      vector("--rotate", o.rotation, "turn the cube about x, then y, then z, degrees", "AX AY AZ");
  o.velocityOption =
      vector("--velocity", o.velocity, "velocity of every point VX VY VZ, m/s", "VX VY VZ");
  o.spinOption = vector("--spin", o.spin, "rigid angular velocity WX WY WZ about the centre, rad/s",
                        "WX WY WZ");
  o.skewOption =
      vector("--skew-corner", o.skew, "displace corner p[7][7][7] by DX DY DZ, m", "DX DY DZ");
  app.add_flag("--inside-out", o.insideOut,
               "reflect the cube through its centre: every face faces in")
      ->group("Initial state");
  o.sizeOption->excludes(o.fromOption);
}

}  // namespace

void addCreateWorldOptions(CLI::App& app, CreateWorldOptions& o) {
  addGeneralOptions(app, o);
  addParameterOptions(app, o);
  addFieldOptions(app, o);
  addStateOptions(app, o);
}

}  // namespace jello
