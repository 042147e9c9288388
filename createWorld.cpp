// createWorld.cpp (the course's file): createWorld's main. The program is app/createworld.cpp;
// here it is run, its failure printed as one line and its exit status chosen (README: createWorld).

#include "app/createworld.h"

#include "core/exitstatus.h"
#include "core/output.h"

int main(int argc, char** argv) {
  jello::setProgramName("createWorld");
  jello::installSignalCleanup();
  return jello::runMain("not enough memory for this world",
                        [&] { return jello::createWorldCommand(argc, argv); });
}
