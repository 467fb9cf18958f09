#pragma once

#include "raylab/core/AlgorithmInfo.h"
#include "raylab/core/PixelTrace.h"
#include "raylab/core/RayTree.h"
#include "raylab/core/RenderSettings.h"
#include "raylab/core/Scene.h"
#include "raylab/core/SceneIO.h"
#include "raylab/core/Tracer.h"

#include <random>
#include <string>

/// \file RayTreeFixtures.h
/// Trees for the ray-tree tests: real ones traced on lessons/scenes/materials.json, and
/// synthetic random ones of any size.

namespace raylab::testing {

/// Baseline threshold of ray-tree pictures (compareImages' scale), 10x tighter than the
/// default: rays are thin lines over few pixels. Measured on the Whitted glass tree at
/// 320x240: hiding its 5 shadow rays 1.8e-4 (the default 2e-4 would forgive it), colouring
/// by kind instead of energy 2.7e-3, no tree 3.5e-3; a repeated render 0.
constexpr double kRayTreeBaselineThreshold = 2e-5;

/// Pixel of the materials scene (320x240) on the glass sphere, left of its centre, where
/// Whitted refracts through the glass and the stochastic algorithms branch.
constexpr int kGlassPixelX = 64;
constexpr int kGlassPixelY = 150;

inline Scene materialsScene() {
  return SceneIO::load(std::string(RAYLAB_SOURCE_DIR) + "/lessons/scenes/materials.json");
}

/// Sample `sample` of pixel (x, y) under `algorithm`, seed 1, traced as the window does.
inline PixelTrace tracePixelOf(const Scene& scene, Algorithm algorithm, int x, int y,
                               int sample = 0) {
  RenderSettings settings = scene.render;
  settings.algorithm = algorithm;
  settings.seed = 1;
  return tracePixel(scene, settings, x, y, sample);
}

/// The recorded tree of sample 0 of pixel (x, y) under `algorithm`, seed 1.
inline RayTree traceTree(const Scene& scene, Algorithm algorithm, int x, int y, int sample = 0) {
  return tracePixelOf(scene, algorithm, x, y, sample).tree;
}

inline RayTree traceGlassPixel(const Scene& scene, Algorithm algorithm) {
  return traceTree(scene, algorithm, kGlassPixelX, kGlassPixelY);
}

}  // namespace raylab::testing

namespace raylab::testing {

/**
 * \brief A random tree of `count` segments with the engine's invariants: breadth-first
 * ids, children of a ray consecutive, parent before child, depth = parent's + 1, a child
 * starting where its parent ended. Kinds, hits, blocked shadow rays and energies vary
 * (some zero, the rest spread over the energy scale).
 */
inline RayTree randomTree(int count, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  RayTree tree;
  tree.segments.resize(std::size_t(count));
  int next = 1;  // id of the next child to hand out
  for (int i = 0; i < count; ++i) {
    RaySegment& s = tree.segments[std::size_t(i)];
    s.id = i;
    if (i == 0) {
      s.kind = RayKind::Camera;
      s.origin = Point3(0.0, 1.0, 5.0);
    } else {
      const RaySegment& p = tree.segments[std::size_t(s.parent)];
      s.depth = p.depth + 1;
      s.origin = p.endPoint;
      s.kind = RayKind(1 + int(u(rng) * (kRayKindCount - 1)));
      // The last open ray must branch, or the tree would end before `count` rays.
      if (next == i + 1 && s.kind == RayKind::Shadow) s.kind = RayKind::Diffuse;
    }
    s.direction = glm::normalize(Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5 - 1e-3));
    s.endPoint = s.origin + (0.5 + 2.0 * u(rng)) * s.direction;
    s.hit = u(rng) < 0.8;
    s.normal = -s.direction;
    s.throughput = Vec3(std::pow(10.0, -4.0 * u(rng)));
    const bool lit = u(rng) < 0.3;
    s.emitted = lit ? Vec3(0.5 * u(rng)) : Vec3(0.0);
    int children = 0;
    if (s.kind == RayKind::Shadow) {
      s.hit = !lit;
      s.lightPoint = s.endPoint + s.direction;
      s.endReason = lit ? EndReason::ReachedLight : EndReason::Occluded;
    } else {
      children = std::min(count - next, 1 + int(u(rng) * 3.0));
      s.endReason =
          children > 0 ? EndReason::Spawned : (s.hit ? EndReason::Absorbed : EndReason::Escaped);
    }
    if (children > 0) {
      s.firstChild = next;
      s.childCount = children;
      for (int c = 0; c < children; ++c) tree.segments[std::size_t(next + c)].parent = i;
      next += children;
    }
  }
  tree.propagate();
  return tree;
}

}  // namespace raylab::testing
