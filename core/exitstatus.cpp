// core/exitstatus.cpp: an outcome's exit status (exitstatus.h).

#include "core/exitstatus.h"

#include <exception>
#include <new>
#include <string>

#include "core/output.h"

namespace jello {

int exitStatusOf(const Outcome& outcome) {
  if (!outcome.message.empty()) printError(outcome.message);
  switch (outcome.status) {
    case Ending::Ok:
      return kExitOk;
    case Ending::Diverged:
      return kExitDiverged;
    case Ending::Failed:
      return kExitBadInput;
  }
  return kExitBadInput;
}

int runMain(const char* outOfMemory, const std::function<Outcome()>& command) {
  int status = kExitBadInput;
  try {
    status = exitStatusOf(command());
  } catch (const std::bad_alloc&) {
    printError(outOfMemory);
  } catch (const std::exception& e) {
    printError(e.what());
  }
  if (const std::string unwritten = unwrittenStandardOutput(); !unwritten.empty()) {
    printError(unwritten);
    if (status == kExitOk) status = kExitBadInput;
  }
  return status;
}

}  // namespace jello
