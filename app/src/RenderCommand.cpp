#include "RenderCommand.h"

#include "ExitCodes.h"
#include "SceneSource.h"

#include "raylab/core/Image.h"
#include "raylab/core/Renderer.h"
#include "raylab/vis/ImageIO.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <sstream>

#include <unistd.h>

namespace raylab::app {

namespace {

std::string lowerExtension(const std::string& path) {
  const std::size_t dot = path.find_last_of('.');
  const std::size_t slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {};
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

/// The renderer's float image as vis's 8-bit picture (clamp, sRGB).
Image toPicture(const FloatImage& image) {
  Image picture(image.width, image.height);
  picture.rgb = imageio::toSrgb8(image);
  return picture;
}

/// "[#########.........]  45%" on a terminal (redrawn in place), "render: 45%" otherwise.
void reportProgress(double fraction, int samples, bool terminal) {
  const int percent = static_cast<int>(fraction * 100.0 + 0.5);
  if (terminal) {
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(fraction * kWidth + 0.5);
    std::cerr << "\r[" << std::string(filled, '#') << std::string(kWidth - filled, '.') << "] "
              << std::setw(3) << percent << "% " << samples << " spp" << std::flush;
    if (fraction >= 1.0) std::cerr << "\n";
  } else {
    std::cerr << "render: " << percent << "% (" << samples << " spp)" << std::endl;
  }
}

}  // namespace

bool isRenderOutput(const std::string& path) {
  const std::string ext = lowerExtension(path);
  return ext == ".png" || ext == ".ppm" || ext == ".pfm";
}

int runRender(const RenderOptions& options) {
  // Step 1: the scene and the settings: the scene's render block, then the command line.
  Scene scene = loadSceneOrDefault(options.scene);
  RenderSettings settings = scene.render;
  if (options.algorithm) settings.algorithm = *parseAlgorithm(*options.algorithm);
  if (options.spp) settings.samplesPerPixel = *options.spp;
  if (options.seed) settings.seed = *options.seed;
  if (options.width > 0 && options.height > 0) {
    scene.camera.width = options.width;
    scene.camera.height = options.height;
  }

  // Step 2: render, reporting each pass.
  Renderer renderer(scene, settings);
  renderer.setThreads(options.threads);
  const bool terminal = ::isatty(STDERR_FILENO) == 1;
  renderer.setProgress([&](double fraction, const FloatImage&) {
    reportProgress(fraction, static_cast<int>(fraction * settings.samplesPerPixel + 0.5), terminal);
  });
  const FloatImage image = renderer.render();

  // Step 3: write the image in the format its extension names.
  const std::string ext = lowerExtension(options.out);
  if (ext == ".pfm") {
    imageio::writePfm(image, options.out);
  } else if (ext == ".ppm") {
    imageio::writePpm(image, options.out);
  } else {
    ImageIO::writePng(toPicture(image), options.out);
  }

  // Step 4: the figures.
  const RenderStats& stats = renderer.stats();
  std::cout << options.out << "\n";
  std::cout << "algorithm " << toString(settings.algorithm) << ", " << image.width << "x"
            << image.height << ", " << stats.samplesPerPixel << " spp, seed " << settings.seed
            << "\n";
  std::cout << "rays:";
  for (int k = 0; k < kRayKindCount; ++k)
    std::cout << " " << toString(static_cast<RayKind>(k)) << " " << stats.rays.byKind[k] << ",";
  std::cout << " total " << stats.rays.total() << "\n";
  const double samples = double(image.width) * image.height * stats.samplesPerPixel;
  std::cout << std::fixed << std::setprecision(3) << "time: " << stats.seconds << " s ("
            << std::setprecision(0) << (stats.seconds > 0.0 ? samples / stats.seconds : 0.0)
            << " samples/s)" << std::endl;
  if (stats.nonFiniteSamples > 0)
    std::cerr << "raylab: warning: " << stats.nonFiniteSamples
              << " samples were NaN or infinite and were counted as black" << std::endl;
  return kExitOk;
}

}  // namespace raylab::app
