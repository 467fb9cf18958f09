#pragma once

#include "raylab/core/Exception.h"
#include "raylab/vis/Image.h"

#include <string>

namespace raylab {

/// Reading and writing PNG files (through VTK's PNG reader and writer).
class ImageIO {
 public:
  /// A PNG that cannot be read or written; the message names the file and the reason.
  class Error : public Exception {
   public:
    explicit Error(const std::string& message) : Exception(message) {}
  };

  /// Reads an 8-bit RGB, RGBA, grey or grey+alpha PNG; alpha is dropped, grey expanded.
  /// Throws Error naming the file when it is missing or not a PNG.
  static Image readPng(const std::string& path);
  /// Writes an RGB PNG. Throws Error naming the file when it cannot be written; never
  /// leaves a partial file under `path` (writes a temporary file, then renames it).
  static void writePng(const Image& image, const std::string& path);
};

}  // namespace raylab
