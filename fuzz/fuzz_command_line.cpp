// libFuzzer target: jello's command line, parsed only (see checks.h for what is asserted).
#include "checks.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  jello::fuzz::checkCommandLine(data, size);
  return 0;
}
