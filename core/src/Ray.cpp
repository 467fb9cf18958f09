#include "raylab/core/Ray.h"

#include "raylab/core/Check.h"

namespace raylab {

std::string Ray::toString() const {
  return "Ray[o=" + raylab::toString(origin) + ", d=" + raylab::toString(direction) + ", t in [" +
         std::to_string(tMin) + ", " + std::to_string(tMax) + "], time=" + std::to_string(time) +
         "]";
}

}  // namespace raylab
