#pragma once

#include "raylab/core/Language.h"
#include "raylab/core/RenderSettings.h"
#include "raylab/core/Scene.h"
#include "raylab/vis/BvhStyle.h"

#include <cstdint>
#include <string>

/// \file BvhCaptions.h
/// The words of lesson 8's pictures: what the BVH view shows, how an image's meshes were
/// searched, and the rays per second measured. One wording for the window's lesson player
/// and `raylab lesson`'s handouts, in English or Simplified Chinese (UTF-8).

namespace raylab::vis {

/// "surface area heuristic" or "median split"; "表面积启发式", "中位数划分".
std::string splitName(BvhSettings::Split split, Language language = Language::English);

/// What the BVH view draws, with its figures: the mesh, the split, the levels and the
/// boxes; with a ray (its pixel given), the boxes it entered, missed and culled and its
/// ray/triangle tests against the mesh's triangle count. Empty when nothing is drawn.
std::string bvhCaption(const Scene& scene, const BvhStyle& style, const BvhSummary& summary,
                       Language language = Language::English, int pixelX = -1, int pixelY = -1);

/// How a render searches the scene's meshes: "Meshes searched through their BVH (surface
/// area heuristic)." or "Brute force: every ray tested against every triangle (no BVH)."
std::string searchCaption(const RenderSettings& settings, Language language = Language::English);

/// A render's speed: "Measured: 1.23 M rays in 0.52 s, 2.37 M rays/s." (machine-dependent).
std::string speedCaption(std::uint64_t rays, double seconds, Language language = Language::English);

}  // namespace raylab::vis
