#include "raylab/core/Check.h"

#include <cstdio>
#include <cstdlib>

namespace raylab::detail {

void checkFailed(const char* file, int line, const std::string& what) {
  std::fprintf(stderr, "%s:%d: RAYLAB_CHECK failed: %s\n", file, line, what.c_str());
  std::abort();
}

}  // namespace raylab::detail
