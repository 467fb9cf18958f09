#pragma once

#include "raylab/core/Bvh.h"
#include "raylab/core/Language.h"
#include "raylab/core/Ray.h"
#include "raylab/core/Types.h"

namespace raylab {
struct LessonStep;
struct Scene;
}  // namespace raylab

#include <optional>

namespace raylab::vis {

/**
 * \brief What the 3D view draws of a mesh's bounding volume hierarchy (lesson 8): the
 * boxes of some levels as wireframes, coloured by level, and optionally the boxes one ray
 * meets while it searches the hierarchy for its nearest hit.
 *
 * - Without a ray: every box of levels firstLevel..lastLevel, in its level's colour
 *   (bvhLevelColour). Leaves shallower than firstLevel are not drawn.
 * - With a ray: only the boxes of those levels the ray's search met (Bvh::traceVisits):
 *   the boxes it entered thick, in their level's colour; the boxes it missed thin and
 *   dark grey; the boxes it culled (met only beyond the nearest hit found so far) thin
 *   and light grey.
 *
 * The hierarchy drawn is the one a render with `split` searches (SceneIntersector), and
 * the mesh is drawn see-through (opacity 0.35) while its boxes are shown, so the boxes
 * inside it can be seen.
 */
struct BvhStyle {
  int object = -1;     ///< Index of the mesh object in Scene::objects; -1: nothing drawn.
  int firstLevel = 0;  ///< First level drawn (depth from the root: the root is level 0).
  int lastLevel = 0;   ///< Last level drawn, inclusive.
  BvhSettings::Split split = BvhSettings::Split::Sah;  ///< The hierarchy's split.
  std::optional<Ray> ray;  ///< A ray (world space) whose visited boxes are shown.
  /// The words of the legend the view draws in its top right corner (which colour is which
  /// level; with a ray, the greys of missed and culled boxes).
  Language language = Language::English;

  bool shown() const { return object >= 0; }
};

/// What a BvhStyle draws, counted: for captions in the window and the lesson handouts.
struct BvhSummary {
  int depth = 0;          ///< Deepest level of the hierarchy (the root: 0).
  int nodes = 0;          ///< Nodes (boxes) of the hierarchy.
  int boxes = 0;          ///< Boxes drawn.
  int entered = 0;        ///< With a ray: drawn boxes it entered ...
  int missed = 0;         ///< ... passed by ...
  int culled = 0;         ///< ... and met only beyond its nearest hit so far.
  int triangleTests = 0;  ///< With a ray: its ray/triangle tests (all levels).
  bool hit = false;       ///< With a ray: it hits the mesh.
};

/// Counts what `style` draws of `scene` (nothing when style.object is not a mesh).
BvhSummary summarizeBvh(const Scene& scene, const BvhStyle& style);

/// The style of a lesson step's "bvh" block (LessonBvh): its mesh and levels, the split of
/// the step's settings, and with `visits` the camera ray of the step's pixel. A step
/// without the block gives the empty style (nothing drawn).
BvhStyle lessonBvhStyle(const LessonStep& step);

/// Colour of the boxes of level `depth` (linear RGB in [0, 1]): yellow, orange, pink,
/// cyan, blue, lime, red, white, then again from yellow.
Vec3 bvhLevelColour(int depth);
/// Colours of a ray's missed and culled boxes (greys, never a level colour).
Vec3 bvhMissedColour();
Vec3 bvhCulledColour();

}  // namespace raylab::vis
