#pragma once

// Scenes and statistics shared by the light-transport suites (TestTracer, TestAlgorithms,
// TestConvergence). Every scene is built in code so its expected values can be derived by
// hand beside the tests.

#include "raylab/core/Box.h"
#include "raylab/core/Quad.h"
#include "raylab/core/Scene.h"
#include "raylab/core/Sphere.h"
#include "raylab/core/Tracer.h"

#include <cmath>
#include <memory>
#include <string>

namespace raylab::testing {

/// A material with the fields the tests vary; the rest keep Material's defaults.
inline Material makeMaterial(const std::string& name, MaterialType type, const Vec3& colour,
                             const Vec3& emission = Vec3(0.0)) {
  Material m;
  m.name = name;
  m.type = type;
  m.colour = colour;
  m.emission = emission;
  return m;
}

/// Appends a material and returns its index.
inline int addMaterial(Scene& scene, const Material& m) {
  scene.materials.push_back(m);
  return int(scene.materials.size()) - 1;
}

/// Appends an object and returns its index.
inline int addObject(Scene& scene, const std::string& name, std::unique_ptr<Shape> shape,
                     int material) {
  scene.objects.emplace_back(name, std::move(shape), material);
  return int(scene.objects.size()) - 1;
}

/// The six faces of the box [lo, hi] as quads whose front sides face inwards, each with
/// its own material index (order: floor, ceiling, back (-z), front (+z), left (-x), right).
inline void addInwardBox(Scene& scene, const Point3& lo, const Point3& hi, const int materials[6],
                         bool withFront = true) {
  const Vec3 d = hi - lo;
  addObject(scene, "floor",
            std::make_unique<Quad>(Point3(lo.x, lo.y, hi.z), Vec3(d.x, 0, 0), Vec3(0, 0, -d.z)),
            materials[0]);
  addObject(scene, "ceiling",
            std::make_unique<Quad>(Point3(lo.x, hi.y, lo.z), Vec3(d.x, 0, 0), Vec3(0, 0, d.z)),
            materials[1]);
  addObject(scene, "back wall",
            std::make_unique<Quad>(Point3(lo.x, lo.y, lo.z), Vec3(d.x, 0, 0), Vec3(0, d.y, 0)),
            materials[2]);
  if (withFront)
    addObject(scene, "front wall",
              std::make_unique<Quad>(Point3(hi.x, lo.y, hi.z), Vec3(-d.x, 0, 0), Vec3(0, d.y, 0)),
              materials[3]);
  addObject(scene, "left wall",
            std::make_unique<Quad>(Point3(lo.x, lo.y, hi.z), Vec3(0, 0, -d.z), Vec3(0, d.y, 0)),
            materials[4]);
  addObject(scene, "right wall",
            std::make_unique<Quad>(Point3(hi.x, lo.y, lo.z), Vec3(0, 0, d.z), Vec3(0, d.y, 0)),
            materials[5]);
}

/**
 * The furnace: a closed cube [-1, 1]^3 whose inner faces are all Diffuse with albedo `a`
 * and emit `Le`; the camera sits at the centre. Every ray sees L = Le + a L, so
 * L = Le / (1 - a) in every pixel.
 */
inline Scene furnaceScene(double albedo, double Le) {
  Scene scene;
  scene.name = "furnace";
  const int m = addMaterial(
      scene, makeMaterial("furnace wall", MaterialType::Diffuse, Vec3(albedo), Vec3(Le)));
  const int faces[6] = {m, m, m, m, m, m};
  addInwardBox(scene, Point3(-1.0), Point3(1.0), faces);
  scene.camera.position = Point3(0.0);
  scene.camera.lookAt = Point3(0.3, 0.2, -1.0);
  scene.camera.verticalFov = 90.0;
  scene.camera.width = 8;
  scene.camera.height = 8;
  return scene;
}

/**
 * A room with every material: diffuse walls, a black area light on the ceiling, a point
 * light, a mirror sphere, a glass sphere, a glossy sphere, the original course program's
 * mirror (reflection and refraction rates) on a box, and a diffuse box.
 * Room [-2, 2] x [0, 3] x [-3, 1].
 */
inline Scene allMaterialsScene(int width = 16, int height = 12) {
  Scene scene;
  scene.name = "all materials";
  const int white = addMaterial(scene, makeMaterial("white", MaterialType::Diffuse, Vec3(0.7)));
  const int red = addMaterial(scene, makeMaterial("red", MaterialType::Diffuse, {0.7, 0.1, 0.1}));
  const int green =
      addMaterial(scene, makeMaterial("green", MaterialType::Diffuse, {0.1, 0.6, 0.1}));
  const int light = addMaterial(
      scene, makeMaterial("light", MaterialType::Diffuse, Vec3(0.0), Vec3(12.0, 10.0, 8.0)));
  Material mirror = makeMaterial("mirror", MaterialType::Mirror, Vec3(0.95));
  mirror.reflectionRate = 0.9;
  mirror.refractionRate = 0.0;
  Material seedMirror = makeMaterial("seed mirror", MaterialType::Mirror, {0.9, 0.9, 0.6});
  seedMirror.reflectionRate = 0.3;
  seedMirror.refractionRate = 0.6;
  seedMirror.ior = 1.3;
  Material glass = makeMaterial("glass", MaterialType::Dielectric, Vec3(1.0));
  glass.ior = 1.5;
  Material glossy = makeMaterial("glossy", MaterialType::Glossy, {0.8, 0.6, 0.2});
  glossy.exponent = 30.0;
  glossy.specular = 0.6;
  const int mirrorM = addMaterial(scene, mirror);
  const int seedM = addMaterial(scene, seedMirror);
  const int glassM = addMaterial(scene, glass);
  const int glossyM = addMaterial(scene, glossy);

  const int faces[6] = {white, white, white, white, red, green};
  addInwardBox(scene, Point3(-2.0, 0.0, -3.0), Point3(2.0, 3.0, 1.0), faces, false);
  addObject(scene, "area light",
            std::make_unique<Quad>(Point3(-0.5, 2.99, -1.5), Vec3(1, 0, 0), Vec3(0, 0, 1)), light);
  addObject(scene, "mirror sphere", std::make_unique<Sphere>(Point3(-1.1, 0.6, -2.0), 0.6),
            mirrorM);
  addObject(scene, "glass sphere", std::make_unique<Sphere>(Point3(0.9, 0.5, -1.0), 0.5), glassM);
  addObject(scene, "glossy sphere", std::make_unique<Sphere>(Point3(0.2, 0.45, -2.2), 0.45),
            glossyM);
  addObject(scene, "seed mirror box",
            std::make_unique<Box>(Point3(1.2, 0.4, -2.4), Vec3(0.8, 0.8, 0.8)), seedM);
  addObject(scene, "diffuse box", std::make_unique<Box>(Point3(-0.5, 0.25, -0.8), Vec3(0.5)),
            white);
  PointLight point;
  point.name = "point light";
  point.position = {1.0, 2.5, 0.0};
  point.intensity = Vec3(3.0);
  scene.pointLights.push_back(point);

  scene.camera.position = {0.0, 1.5, 3.5};
  scene.camera.lookAt = {0.0, 1.2, -1.5};
  scene.camera.verticalFov = 50.0;
  scene.camera.width = width;
  scene.camera.height = height;
  return scene;
}

/**
 * A Cornell-like box: white floor, ceiling and back wall, red left and green right walls,
 * a square light under the ceiling, a tall and a short box. Area light only (no point
 * light), so path tracing with and without next-event estimation see the same light.
 */
inline Scene cornellScene(int width, int height) {
  Scene scene;
  scene.name = "cornell";
  const int white = addMaterial(scene, makeMaterial("white", MaterialType::Diffuse, Vec3(0.73)));
  const int red =
      addMaterial(scene, makeMaterial("red", MaterialType::Diffuse, {0.65, 0.05, 0.05}));
  const int green =
      addMaterial(scene, makeMaterial("green", MaterialType::Diffuse, {0.12, 0.45, 0.15}));
  const int light = addMaterial(
      scene, makeMaterial("light", MaterialType::Diffuse, Vec3(0.0), Vec3(6.0, 5.2, 4.0)));
  const int faces[6] = {white, white, white, white, red, green};
  addInwardBox(scene, Point3(-1.0, 0.0, -2.0), Point3(1.0, 2.0, 0.0), faces, false);
  addObject(scene, "light",
            std::make_unique<Quad>(Point3(-0.4, 1.999, -1.4), Vec3(0.8, 0, 0), Vec3(0, 0, 0.8)),
            light);
  addObject(scene, "tall box", std::make_unique<Box>(Point3(-0.35, 0.6, -1.3), Vec3(0.6, 1.2, 0.6)),
            white);
  addObject(scene, "short box", std::make_unique<Box>(Point3(0.4, 0.3, -0.8), Vec3(0.6)), white);
  scene.camera.position = {0.0, 1.0, 2.6};
  scene.camera.lookAt = {0.0, 1.0, -1.0};
  scene.camera.verticalFov = 40.0;
  scene.camera.width = width;
  scene.camera.height = height;
  return scene;
}

/// Render settings for one algorithm with the given samples per pixel.
inline RenderSettings settingsFor(Algorithm algorithm, int spp, std::uint64_t seed = 1) {
  RenderSettings s;
  s.algorithm = algorithm;
  s.samplesPerPixel = spp;
  s.seed = seed;
  return s;
}

/// Running mean and variance of independent samples, per channel (Welford).
struct RunningStats {
  long long n = 0;
  Vec3 mean{0.0};
  Vec3 m2{0.0};
  void add(const Vec3& x) {
    ++n;
    const Vec3 delta = x - mean;
    mean += delta / double(n);
    m2 += delta * (x - mean);
  }
  /// Sample variance of one sample.
  Vec3 variance() const { return n > 1 ? m2 / double(n - 1) : Vec3(0.0); }
  /// Standard error of the mean.
  Vec3 standardError() const { return glm::sqrt(variance() / double(n)); }
};

inline bool isFiniteVec(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace raylab::testing
