#include "scene/SceneFields.h"

#include "raylab/core/Limits.h"
#include "raylab/core/SceneIO.h"
#include "raylab/core/Transform.h"

#include <cmath>
#include <filesystem>

namespace raylab {

SceneFields::SceneFields(std::string origin)
    : m_origin(std::move(origin)),
      m_baseDir(std::filesystem::path(m_origin).parent_path().string()) {}

void SceneFields::fail(const std::string& path, const std::string& what) const {
  throw SceneIO::LoadError(m_origin + ": at " + (path.empty() ? "/" : path) + ": " + what);
}

double SceneFields::bounded(const json& j, const std::string& path) const {
  const double v = number(j, path);
  if (std::abs(v) > limits::kMaxCoordinate)
    fail(path, excerpt(j) + " is beyond RayLab's largest coordinate, 1e12");
  return v;
}

Vec3 SceneFields::vec3(const json& j, const std::string& path) const {
  if (!j.is_array() || j.size() != 3) fail(path, "expected [x, y, z], got " + excerpt(j));
  return {bounded(j[0], path + "/0"), bounded(j[1], path + "/1"), bounded(j[2], path + "/2")};
}

double SceneFields::length(const json& j, const std::string& path, const char* what) const {
  const double v = bounded(j, path);
  if (v <= 0.0) fail(path, std::string(what) + " must be positive, got " + excerpt(j));
  if (v < limits::kMinLength)
    fail(path, std::string(what) + " " + excerpt(j) + " is below RayLab's smallest size, 1e-9");
  return v;
}

Vec3 SceneFields::nonZero(const json& j, const std::string& path) const {
  const Vec3 v = vec3(j, path);
  if (v == Vec3(0.0)) fail(path, "vector must not be zero (it gives a direction)");
  if (glm::length(v) < limits::kMinLength)
    fail(path, "vector is too short to give a direction (length below 1e-9)");
  return v;
}

Mat4 SceneFields::matrix(const json& j, const std::string& path) const {
  if (!j.is_array() || j.size() != 4) fail(path, "expected 4 rows of 4 numbers");
  Mat4 m(1.0);
  for (int r = 0; r < 4; ++r) {
    const std::string rp = path + "/" + std::to_string(r);
    if (!j[r].is_array() || j[r].size() != 4) fail(rp, "expected a row of 4 numbers");
    for (int c = 0; c < 4; ++c) m[c][r] = number(j[r][c], rp + "/" + std::to_string(c));
  }
  if (!isAffine(m)) fail(path, "last row must be [0, 0, 0, 1] (an affine transform)");
  if (glm::determinant(Mat3(m)) == 0.0) fail(path, "matrix is singular");
  return m;
}

}  // namespace raylab
