// Renders a scene file with the installed raylab::core and prints what it made, so that
// the install test sees the headers, the static library and its dependencies work.
//
//   consumer SCENE.json
#include "raylab/core/Renderer.h"
#include "raylab/core/SceneIO.h"

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: consumer SCENE.json\n");
    return 2;
  }
  try {
    raylab::Scene scene = raylab::SceneIO::load(argv[1]);
    scene.camera.width = 32;
    scene.camera.height = 24;
    raylab::RenderSettings settings = scene.render;
    settings.samplesPerPixel = 2;
    raylab::Renderer renderer(scene, settings);
    renderer.setThreads(2);
    const raylab::FloatImage image = renderer.render();
    double sum = 0.0;
    for (const glm::vec3& p : image.pixels) sum += raylab::luminance(raylab::Vec3(p));
    std::printf("consumer: rendered '%s' at %dx%d, %d spp, mean luminance %.4f, %llu rays\n",
                scene.name.c_str(), image.width, image.height, renderer.stats().samplesPerPixel,
                sum / double(image.pixels.size()),
                static_cast<unsigned long long>(renderer.stats().rays.total()));
    return sum > 0.0 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "consumer: %s\n", e.what());
    return 1;
  }
}
