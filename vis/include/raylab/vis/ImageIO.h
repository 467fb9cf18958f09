#pragma once

#include "raylab/core/Exception.h"
#include "raylab/core/Image.h"

#include <string>

/// \file ImageIO.h
/// Image files, written in the format their extension names: the one writer of pictures
/// (PNG through VTK's PNG codec; PPM and PFM through core's imageio).

namespace raylab::vis {

/// An image file that cannot be read or written; the message names the file and the reason.
class ImageError : public Exception {
 public:
  using Exception::Exception;
};

/// Reads an 8-bit RGB, RGBA, grey or grey+alpha PNG; alpha is dropped, grey expanded.
/// Throws ImageError naming the file when it is missing or not a PNG.
SrgbImage readPng(const std::string& path);
/// Writes an RGB PNG: encoded in memory, then written atomically (writeFileAtomically), so
/// `path` is either unchanged or complete. Throws ImageError naming the file.
void writePng(const SrgbImage& image, const std::string& path);

/// True when `path` ends in an extension writeImage knows: .png, .ppm or .pfm.
bool isImageFile(const std::string& path);
/// Writes a rendered image in the format `path`'s extension names: .png (8-bit sRGB),
/// .ppm (8-bit sRGB) or .pfm (linear float). Throws ImageError (or imageio::WriteError)
/// naming the file; the target is never left half written.
void writeImage(const FloatImage& image, const std::string& path);

}  // namespace raylab::vis
