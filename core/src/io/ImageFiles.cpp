#include "raylab/core/Image.h"

#include "raylab/core/AtomicFile.h"
#include "raylab/core/Check.h"
#include "raylab/core/Limits.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <unordered_set>

namespace raylab {

SrgbImage::SrgbImage(int w, int h) : width(std::max(w, 0)), height(std::max(h, 0)) {
  rgb.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3, 0);
}

Rgb8 SrgbImage::at(int x, int y) const {
  RAYLAB_DCHECK(x >= 0 && x < width && y >= 0 && y < height);
  const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 3;
  return {rgb[i], rgb[i + 1], rgb[i + 2]};
}

void SrgbImage::set(int x, int y, const Rgb8& colour) {
  RAYLAB_DCHECK(x >= 0 && x < width && y >= 0 && y < height);
  const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 3;
  rgb[i] = colour[0];
  rgb[i + 1] = colour[1];
  rgb[i + 2] = colour[2];
}

int SrgbImage::distinctColours() const {
  std::unordered_set<std::uint32_t> colours;
  for (std::size_t i = 0; i + 2 < rgb.size(); i += 3) {
    colours.insert((std::uint32_t{rgb[i]} << 16) | (std::uint32_t{rgb[i + 1]} << 8) |
                   std::uint32_t{rgb[i + 2]});
  }
  return static_cast<int>(colours.size());
}

std::string SrgbImage::toString() const {
  return "SrgbImage(" + std::to_string(width) + "x" + std::to_string(height) + ")";
}

namespace imageio {

namespace {

/// Writes `bytes` atomically (see writeFileAtomically), throwing WriteError.
void writeAtomically(const std::string& path, const std::string& bytes) {
  if (auto problem = writeFileAtomically(path, bytes)) throw WriteError(path + ": " + *problem);
}

void checkSize(const FloatImage& image, const std::string& path) {
  if (image.width <= 0 || image.height <= 0 ||
      image.pixels.size() != std::size_t(image.width) * image.height)
    throw WriteError(path + ": image is empty or its pixel count does not match " +
                     std::to_string(image.width) + "x" + std::to_string(image.height));
}

bool hostIsLittleEndian() {
  const std::uint32_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

float byteSwapped(float v) {
  unsigned char b[4];
  std::memcpy(b, &v, 4);
  std::swap(b[0], b[3]);
  std::swap(b[1], b[2]);
  std::memcpy(&v, b, 4);
  return v;
}

}  // namespace

std::string encodePfm(const FloatImage& image, const std::string& name) {
  checkSize(image, name);
  // Header: "PF" (colour), size, and a negative scale for little-endian data.
  std::string bytes =
      "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
  const std::size_t header = bytes.size();
  bytes.resize(header + std::size_t(image.width) * image.height * 12);
  char* out = bytes.data() + header;
  const bool swap = !hostIsLittleEndian();
  // PFM stores the bottom row first.
  for (int y = image.height - 1; y >= 0; --y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const float v = swap ? byteSwapped(image.at(x, y)[c]) : image.at(x, y)[c];
        std::memcpy(out, &v, 4);
        out += 4;
      }
  return bytes;
}

void writePfm(const FloatImage& image, const std::string& path) {
  writeAtomically(path, encodePfm(image, path));
}

namespace {

/// Reads a PFM from `in`; `exact` refuses bytes after the pixels.
/// `remaining`: the stream's size in bytes when known (a file's, a string's).
FloatImage readPfmStream(std::istream& in, const std::string& name, bool exact,
                         std::optional<std::uint64_t> remaining) {
  std::string magic;
  int width = 0, height = 0;
  double scale = 0.0;
  in >> magic >> width >> height >> scale;
  if (!in || magic != "PF")
    throw ReadError(name + ": not a colour PFM file (expected the \"PF\" header)");
  if (width <= 0 || height <= 0 || !std::isfinite(scale) || scale == 0.0)
    throw ReadError(name + ": bad PFM header (size " + std::to_string(width) + "x" +
                    std::to_string(height) + ", scale " + std::to_string(scale) + ")");
  // The image limit before any allocation (issue 38: 65536 x 65536 asked for 48 GB).
  if (width > limits::kMaxImageSide || height > limits::kMaxImageSide ||
      std::int64_t(width) * height > limits::kMaxImagePixels)
    throw ReadError(name + ": the PFM image is " + std::to_string(width) + "x" +
                    std::to_string(height) + "; RayLab's images have sides of at most " +
                    std::to_string(limits::kMaxImageSide) + " and at most 4096 x 4096 pixels");
  in.get();  // the single whitespace character after the scale
  // The data must be there before the image is allocated: a 19-byte header cannot make
  // RayLab touch gigabytes before "truncated".
  const std::uint64_t dataBytes = std::uint64_t(width) * std::uint64_t(height) * 12;
  if (remaining && *remaining < dataBytes + std::uint64_t(in.tellg()))
    throw ReadError(name + ": truncated PFM data (the header announces " + std::to_string(width) +
                    "x" + std::to_string(height) + " pixels, " + std::to_string(dataBytes) +
                    " bytes, the file holds fewer)");
  FloatImage image(width, height);
  std::vector<float> row(std::size_t(width) * 3);
  const bool swap = (scale < 0.0) != hostIsLittleEndian();
  for (int y = height - 1; y >= 0; --y) {
    in.read(reinterpret_cast<char*>(row.data()), std::streamsize(row.size() * 4));
    if (!in) throw ReadError(name + ": truncated PFM data");
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c) {
        const float v =
            swap ? byteSwapped(row[std::size_t(x) * 3 + c]) : row[std::size_t(x) * 3 + c];
        // A NaN or infinite reference would give meaningless error figures (issue 38).
        if (!std::isfinite(v))
          throw ReadError(name + ": pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                          ") is not a finite number");
        image.at(x, y)[c] = v;
      }
  }
  if (exact && in.peek() != std::char_traits<char>::eof())
    throw ReadError(name + ": bytes after the PFM data");
  return image;
}

}  // namespace

FloatImage readPfm(const std::string& path) {
  // A regular file only: a FIFO would block and /dev/zero read without end.
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
    throw ReadError(path + ": not a regular file (a folder or a device?)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ReadError(path + ": cannot open image file");
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  return readPfmStream(in, path, false,
                       ec ? std::nullopt : std::optional<std::uint64_t>(std::uint64_t(size)));
}

FloatImage decodePfm(const std::string& bytes, const std::string& name) {
  std::istringstream in(bytes, std::ios::binary);
  return readPfmStream(in, name, true, std::uint64_t(bytes.size()));
}

double srgbFromLinear(double linear) {
  if (!(linear > 0.0)) return 0.0;  // also NaN
  if (linear >= 1.0) return 1.0;
  // The curve's linear toe below 0.0031308, then the 1/2.4 power segment.
  if (linear <= 0.0031308) return 12.92 * linear;
  return 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

std::uint8_t toSrgb8(double linear) {
  return static_cast<std::uint8_t>(std::lround(255.0 * srgbFromLinear(linear)));
}

SrgbImage toSrgb(const FloatImage& image) {
  SrgbImage picture(image.width, image.height);
  std::size_t i = 0;
  for (const glm::vec3& p : image.pixels)
    for (int c = 0; c < 3; ++c) picture.rgb[i++] = toSrgb8(p[c]);
  return picture;
}

void writePpm(const FloatImage& image, const std::string& path) {
  checkSize(image, path);
  const SrgbImage picture = toSrgb(image);
  std::string bytes =
      "P6\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n255\n";
  bytes.append(reinterpret_cast<const char*>(picture.rgb.data()), picture.rgb.size());
  writeAtomically(path, bytes);
}

double rmse(const FloatImage& a, const FloatImage& b) {
  if (a.width != b.width || a.height != b.height || a.pixels.size() != b.pixels.size())
    throw std::invalid_argument("rmse: images differ in size (" + std::to_string(a.width) + "x" +
                                std::to_string(a.height) + " vs " + std::to_string(b.width) + "x" +
                                std::to_string(b.height) + ")");
  if (a.pixels.empty()) return 0.0;
  double sum = 0.0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double d = double(a.pixels[i][c]) - double(b.pixels[i][c]);
      sum += d * d;
    }
  return std::sqrt(sum / (3.0 * double(a.pixels.size())));
}

}  // namespace imageio
}  // namespace raylab
