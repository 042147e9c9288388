// model/world.cpp: the lattice's labels (world.h).

#include "model/world.h"

#include <string>

namespace jello {

std::string latticeLabel(int q) {
  const int perSlab = kLatticeSize * kLatticeSize;
  return "[" + std::to_string(q / perSlab) + "][" +
         std::to_string((q / kLatticeSize) % kLatticeSize) + "][" +
         std::to_string(q % kLatticeSize) + "]";
}

}  // namespace jello
