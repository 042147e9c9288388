// libFuzzer target: the scene-file reader (see checks.h for what is asserted).
#include "checks.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  jello::fuzz::checkSceneText(data, size);
  return 0;
}
