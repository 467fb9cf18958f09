#pragma once

#include "raylab/core/Exception.h"
#include "raylab/core/Types.h"

#include <cstdint>
#include <string>
#include <vector>

namespace raylab {

/// A float RGB image, linear radiance; row 0 is the top row.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<glm::vec3> pixels;  ///< Row-major, width * height.

  Image() = default;
  Image(int w, int h) : width(w), height(h), pixels(std::size_t(w) * h, glm::vec3(0.0f)) {}
  glm::vec3& at(int x, int y) { return pixels[std::size_t(y) * width + x]; }
  const glm::vec3& at(int x, int y) const { return pixels[std::size_t(y) * width + x]; }
};

/// Image files. Errors throw ImageIO::WriteError naming the path; files are written to a
/// temporary name and renamed, never left half-written.
namespace imageio {
class WriteError : public Exception {
 public:
  using Exception::Exception;
};
/// Linear PFM (Portable Float Map, little-endian, bottom-to-top rows as the format says).
void writePfm(const Image& image, const std::string& path);
/// Tone-mapped 8-bit binary PPM (clamp to [0, 1], sRGB transfer curve).
void writePpm(const Image& image, const std::string& path);
/// 8-bit sRGB bytes, RGBRGB..., top row first (clamp to [0, 1] then the sRGB curve).
std::vector<std::uint8_t> toSrgb8(const Image& image);
/// Root-mean-square error over all channels of two images of the same size.
double rmse(const Image& a, const Image& b);
}  // namespace imageio

}  // namespace raylab
