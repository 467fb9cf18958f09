// How the inspector writes numbers (InspectorFormat.h).
#include "inspect/InspectorFormat.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace raylab::inspect {

std::string vec(const Vec3& v) {
  // Components below 1e-12 of the largest are rounding (a point reconstructed as origin +
  // t d): shown as 0, so (0, 5, 4.441e-16) reads (0, 5, 0).
  const double largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  const auto shown = [&](double x) { return std::abs(x) < 1e-12 * largest ? 0.0 : x; };
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "(%.4g, %.4g, %.4g)", shown(v.x), shown(v.y), shown(v.z));
  return buffer;
}

std::string number(double x, int digits) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, x);
  return buffer;
}

}  // namespace raylab::inspect
