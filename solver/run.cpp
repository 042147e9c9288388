// solver/run.cpp: loading a run (run.h).

#include "solver/run.h"

#include <sys/stat.h>

#include <string>

#include "io/scenereader.h"

namespace jello {

Outcome loadRun(const RunOptions& options, WorldFile* out) {
  try {
    *out = isSceneFile(options.worldPath) ? readSceneFile(options.worldPath)
                                          : readWorldFile(options.worldPath);
  } catch (const InputError& e) {
    struct stat info;
    if (options.worldDefaulted && ::stat(options.worldPath.c_str(), &info) != 0)
      return failed(std::string(e.what()) +
                    " (no WORLD was named, and this default is found only from the project's "
                    "folder; name one: jello path/to/world.w)");
    return failed(e.what());
  }
  RunSettings& run = out->run;
  if (options.integrator) run.integrator = *options.integrator;
  if (options.dt) run.dt = *options.dt;
  if (options.n) run.n = *options.n;
  return succeeded();
}

}  // namespace jello
