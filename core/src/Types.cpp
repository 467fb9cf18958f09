#include "raylab/core/Types.h"

#include "raylab/core/Bounds3.h"

#include <cstdio>

namespace raylab {

std::string toString(const Vec3& v) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "(%.17g, %.17g, %.17g)", v.x, v.y, v.z);
  return buffer;
}

std::string Bounds3::toString() const {
  return "Bounds3[" + raylab::toString(lower) + " .. " + raylab::toString(upper) + "]";
}

}  // namespace raylab
