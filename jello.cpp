// jello.cpp (the course's file): the simulator's main (README: Running). The program is
// app/jellocommand.cpp; here it is run, its failure printed as one line and its exit status
// chosen: 0 done, 1 diverged, 2 bad input or usage (core/exitstatus.h).

#include "app/jellocommand.h"
#include "core/exitstatus.h"
#include "core/output.h"

int main(int argc, char** argv) {
  jello::setProgramName("jello");
  jello::installSignalCleanup();
  return jello::runMain("not enough memory for this run",
                        [&] { return jello::jelloCommand(argc, argv); });
}
