#pragma once

#include "raylab/core/Exception.h"
#include "raylab/core/Types.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace raylab {

/**
 * \brief A float RGB image of linear radiance: what the renderer produces.
 *
 * Row 0 is the top row, pixels left to right. SrgbImage is its 8-bit, display-encoded
 * counterpart (imageio::toSrgb).
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

/// One 8-bit sRGB pixel as stored in PNG files.
using Rgb8 = std::array<std::uint8_t, 3>;

/**
 * \brief An 8-bit sRGB picture: what the 3D view renders, what PNG files hold and what
 * tests inspect.
 *
 * Rows are stored from the top of the picture down (as in PNG files and Qt), pixels from
 * left to right, three bytes (r, g, b) per pixel. Image coordinates (x, y) have x to the
 * right and y down from the top-left corner; pixel (i, j) covers [i, i + 1) x [j, j + 1).
 */
struct SrgbImage {
  int width = 0;                  ///< Pixels across.
  int height = 0;                 ///< Pixels down.
  std::vector<std::uint8_t> rgb;  ///< 3 * width * height bytes, row-major from the top.

  SrgbImage() = default;
  /// A black image of the given size (both at least 0).
  SrgbImage(int width, int height);

  /// True when the image has no pixel.
  bool empty() const { return width <= 0 || height <= 0; }
  /// Pixel at column x, row y (row 0 at the top). Both must be inside the image.
  Rgb8 at(int x, int y) const;
  /// Sets the pixel at column x, row y (row 0 at the top).
  void set(int x, int y, const Rgb8& colour);
  /// Number of distinct colours, a cheap "is anything drawn" measure.
  int distinctColours() const;
  /// "SrgbImage(300x300)".
  std::string toString() const;
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
/// The bytes writePfm writes (throws WriteError naming `name` for an empty image).
std::string encodePfm(const FloatImage& image, const std::string& name = "image");
/// Parses the bytes of a colour PFM file, as readPfm does; errors (ReadError) name `name`.
/// Refuses bytes after the pixels, so a file with anything appended is not read as valid.
FloatImage decodePfm(const std::string& bytes, const std::string& name);
/// Tone-mapped 8-bit binary PPM ("P6"; clamp to [0, 1], sRGB transfer curve).
void writePpm(const FloatImage& image, const std::string& path);

/// The sRGB transfer curve (IEC 61966-2-1) of a linear value clamped to [0, 1]:
/// 12.92 v below 0.0031308, 1.055 v^(1/2.4) - 0.055 above. NaN counts as 0.
double srgbFromLinear(double linear);
/// One channel to 8 bits: round(255 * srgbFromLinear(linear)).
std::uint8_t toSrgb8(double linear);
/// The 8-bit picture of a linear image: clamp to [0, 1], then the sRGB curve.
SrgbImage toSrgb(const FloatImage& image);
/// Root-mean-square error over all channels of two images of the same size (throws
/// std::invalid_argument when the sizes differ).
double rmse(const FloatImage& a, const FloatImage& b);
}  // namespace imageio

}  // namespace raylab
