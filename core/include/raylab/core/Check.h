#pragma once

#include <sstream>
#include <string>

/// \file Check.h
/// Invariant checks. RAYLAB_CHECK is always on, RAYLAB_DCHECK only in debug builds.
/// RAYLAB_CHECK_EQ / _LE print both values on failure. A failed check is a bug in RayLab,
/// not bad input: it aborts with file:line.

namespace raylab::detail {
[[noreturn]] void checkFailed(const char* file, int line, const std::string& what);

template <typename A, typename B>
std::string checkValues(const char* expr, const A& a, const B& b) {
  std::ostringstream out;
  out << expr << " (" << a << " vs " << b << ")";
  return out.str();
}
}  // namespace raylab::detail

#define RAYLAB_CHECK(cond)                                                 \
  do {                                                                     \
    if (!(cond)) ::raylab::detail::checkFailed(__FILE__, __LINE__, #cond); \
  } while (false)

#define RAYLAB_CHECK_OP(a, op, b)                                                \
  do {                                                                           \
    const auto& raylabA_ = (a);                                                  \
    const auto& raylabB_ = (b);                                                  \
    if (!(raylabA_ op raylabB_))                                                 \
      ::raylab::detail::checkFailed(                                             \
          __FILE__, __LINE__,                                                    \
          ::raylab::detail::checkValues(#a " " #op " " #b, raylabA_, raylabB_)); \
  } while (false)

#define RAYLAB_CHECK_EQ(a, b) RAYLAB_CHECK_OP(a, ==, b)
#define RAYLAB_CHECK_LE(a, b) RAYLAB_CHECK_OP(a, <=, b)
#define RAYLAB_CHECK_LT(a, b) RAYLAB_CHECK_OP(a, <, b)

#ifdef NDEBUG
#define RAYLAB_DCHECK(cond) \
  do {                      \
  } while (false)
#else
#define RAYLAB_DCHECK(cond) RAYLAB_CHECK(cond)
#endif
