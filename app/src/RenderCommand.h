#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace raylab::app {

/// Options of `raylab render`; unset options take the scene file's "render" block.
struct RenderOptions {
  std::string out;    ///< Image to write: .png, .ppm (8-bit sRGB) or .pfm (linear).
  std::string scene;  ///< Scene file; empty for the built-in default scene.
  std::optional<std::string> algorithm;  ///< raycast, whitted, distributed or path.
  std::optional<int> spp;                ///< Samples per pixel.
  std::optional<std::uint64_t> seed;     ///< Seed of every random decision.
  int threads = 0;                       ///< Worker threads; 0 = all hardware threads.
  int width = 0;                         ///< Image width, pixels; 0 = the scene camera's.
  int height = 0;                        ///< Image height, pixels; 0 = the scene camera's.
};

/// True when `path` ends in .png, .ppm or .pfm (any case): the formats `render` writes.
bool isRenderOutput(const std::string& path);

/**
 * \brief `raylab render`: renders the scene with one of the four algorithms (core
 * Renderer, all threads, progressive) and writes the image. Shows a progress bar on
 * stderr when stderr is a terminal, else one percentage line per pass; then prints on
 * stdout the path written, the rays traced by kind and the time.
 * \return kExitOk; errors are thrown (raylab::Exception subtypes naming the file).
 */
int runRender(const RenderOptions& options);

}  // namespace raylab::app
