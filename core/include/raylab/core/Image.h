#pragma once

#include "raylab/core/Exception.h"
#include "raylab/core/Types.h"

#include <cstdint>
#include <string>
#include <vector>

namespace raylab {

/**
 * \brief A float RGB image of linear radiance: what the renderer produces.
 *
 * Row 0 is the top row, pixels left to right. Named FloatImage so it can live beside
 * vis's 8-bit `raylab::Image` (the PNG picture) in one program.
 */
struct FloatImage {
  int width = 0;                  ///< Pixels across.
  int height = 0;                 ///< Pixels down.
  std::vector<glm::vec3> pixels;  ///< Linear RGB radiance, row-major from the top.

  FloatImage() = default;
  /// A black image of the given size.
  FloatImage(int w, int h) : width(w), height(h), pixels(std::size_t(w) * h, glm::vec3(0.0f)) {}
  /// Pixel at column x, row y (row 0 at the top).
  glm::vec3& at(int x, int y) { return pixels[std::size_t(y) * width + x]; }
  /// Pixel at column x, row y (row 0 at the top).
  const glm::vec3& at(int x, int y) const { return pixels[std::size_t(y) * width + x]; }
};

/// Image files. Errors throw imageio::WriteError / ReadError naming the path; files are
/// written to a temporary name and renamed, never left half-written.
namespace imageio {
/// An image file that cannot be written; the target is unchanged.
class WriteError : public Exception {
 public:
  using Exception::Exception;
};
/// An image file that cannot be read: missing, not a PFM, truncated.
class ReadError : public Exception {
 public:
  using Exception::Exception;
};

/// Linear PFM (Portable Float Map "PF", little-endian, bottom-to-top rows as the format
/// says).
void writePfm(const FloatImage& image, const std::string& path);
/// Reads a colour PFM ("PF") of either byte order, as written by writePfm.
FloatImage readPfm(const std::string& path);
/// Tone-mapped 8-bit binary PPM ("P6"; clamp to [0, 1], sRGB transfer curve).
void writePpm(const FloatImage& image, const std::string& path);

/// The sRGB transfer curve (IEC 61966-2-1) of a linear value clamped to [0, 1]:
/// 12.92 v below 0.0031308, 1.055 v^(1/2.4) - 0.055 above. NaN counts as 0.
double srgbFromLinear(double linear);
/// One channel to 8 bits: round(255 * srgbFromLinear(linear)).
std::uint8_t toSrgb8(double linear);
/// 8-bit sRGB bytes, RGBRGB..., top row first (clamp to [0, 1] then the sRGB curve).
std::vector<std::uint8_t> toSrgb8(const FloatImage& image);
/// Root-mean-square error over all channels of two images of the same size (throws
/// std::invalid_argument when the sizes differ).
double rmse(const FloatImage& a, const FloatImage& b);
}  // namespace imageio

}  // namespace raylab
