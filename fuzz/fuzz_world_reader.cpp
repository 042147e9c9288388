// libFuzzer target: the world-file reader (see checks.h for what is asserted).
#include "checks.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  jello::fuzz::checkWorldText(data, size);
  return 0;
}
