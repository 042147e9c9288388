// app/createworldoptions.h: createWorld's command line (README: createWorld), as CLI11 fills it
// in: each option's value, and the option itself, to ask whether it was given.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace jello {

// What the command line says, filled in by CLI11: the values, and the options to ask whether
// each was given. Bound by address to the App, so it stays where it is made (no copies).
struct CreateWorldOptions {
  CreateWorldOptions() = default;
  CreateWorldOptions(const CreateWorldOptions&) = delete;
  CreateWorldOptions& operator=(const CreateWorldOptions&) = delete;

  std::string output, describe, preset, from;
  bool force = false;
  double maxMemory = 0;
  CLI::Option *describeOption = nullptr, *maxMemoryOption = nullptr, *presetOption = nullptr,
              *fromOption = nullptr;

  std::string integrator;
  double dt = 0, kElastic = 0, dElastic = 0, kCollision = 0, dCollision = 0, mass = 0;
  int n = 0;
  std::vector<double> plane;
  CLI::Option *integratorOption = nullptr, *dtOption = nullptr, *nOption = nullptr,
              *kElasticOption = nullptr, *dElasticOption = nullptr, *kCollisionOption = nullptr,
              *dCollisionOption = nullptr, *massOption = nullptr, *planeOption = nullptr,
              *noPlaneOption = nullptr;

  int resolution = 0;
  std::vector<double> uniform, gravity;
  double swirl = 0, radial = 0;
  std::string expression, fieldFrom;
  CLI::Option* gravityOption = nullptr;
  CLI::Option *resolutionOption = nullptr, *uniformOption = nullptr, *swirlOption = nullptr,
              *radialOption = nullptr, *expressionOption = nullptr, *fieldFromOption = nullptr;
  std::vector<CLI::Option*> fieldSources;  // the options that each give the whole field

  double cubeSize = 1;
  std::vector<double> center, rotation, velocity, spin, skew;
  bool insideOut = false;
  CLI::Option *sizeOption = nullptr, *centerOption = nullptr, *rotateOption = nullptr,
              *velocityOption = nullptr, *spinOption = nullptr, *skewOption = nullptr;
};

// Adds every option of createWorld to `app`, bound to `o`, with the groups and help of --help.
void addCreateWorldOptions(CLI::App& app, CreateWorldOptions& o);

}  // namespace jello
