#pragma once

#include "raylab/core/Bounds3.h"
#include "raylab/core/RayTree.h"
#include "raylab/core/Scene.h"
#include "raylab/core/Types.h"

#include <optional>
#include <string>
#include <vector>

namespace raylab::vis {

/**
 * \brief The camera of the 3D view (the teacher's eye on the scene), not the scene's own
 * camera: it looks at the scene, the scene camera's body and its frustum from outside.
 *
 * A pinhole looking from `eye` at `focalPoint` with vertical field of view `viewAngle`,
 * the same model as VTK's vtkCamera (perspective, view angle in degrees).
 */
struct ViewCamera {
  Point3 eye{0.0, 0.0, 10.0};  ///< Eye position, world space.
  Point3 focalPoint{0.0};      ///< Point looked at, world space.
  Vec3 up{0.0, 1.0, 0.0};      ///< View-up direction, world space.
  double viewAngle = 30.0;     ///< Full vertical field of view, degrees.

  /// Unit direction from the eye to the focal point, world space.
  Vec3 direction() const;
  std::string toString() const;
};

/// Edge length of the scene camera's body glyph, world units: 6% of the diagonal of the
/// bounded objects, so the glyph scales with the room.
double cameraGlyphSize(const Scene& scene);

/// For each object of `scene`: whether it is an enclosing wall, a sphere so large (radius
/// over 100 times the scene camera's viewing distance, the distance to what its central
/// ray meets) that it stands for a flat wall around the scene, as smallpt's six walls of
/// radius 1e5 do. The view draws such walls as patches of the sphere around the room,
/// cut away where they face the viewer (as the Cornell box's open front), and leaves them
/// out of the bounds it frames.
std::vector<bool> enclosingWalls(const Scene& scene);
/// The room the scene camera looks into: the box of the first hits of a grid of its
/// camera rays, or an empty box when none hits anything.
Bounds3 roomBounds(const Scene& scene);

/// World-space box around everything the 3D view draws with a finite size: every bounded
/// shape (planes are unbounded and left out), the scene camera's body and frustum. Never
/// empty: a scene of planes only gives a box of size 2 around the camera's look-at point.
Bounds3 drawnBounds(const Scene& scene);

/**
 * \brief The default 3D view: from behind and above the scene camera, turned 25 degrees
 * about the world up axis and looking 28 degrees down, at the centre of `drawnBounds`,
 * and just far enough back that all 8 corners of `drawnBounds` fit in the picture of
 * aspect ratio `aspect` (width / height) with a 5% margin.
 *
 * The room's walls are drawn one-sided, facing the room (see SceneView), so the walls
 * between this eye and the room do not hide its contents.
 */
ViewCamera defaultViewCamera(const Scene& scene, double aspect = 1.0);

/**
 * \brief Where a world point appears in a width x height picture taken by `camera`.
 *
 * Uses VTK's projection of the same camera (vtkCamera's composite projection matrix with
 * aspect width / height, as vtkRenderer::WorldToDisplay does), then flips to image
 * coordinates: x to the right and y down from the top-left corner, in pixels, so pixel
 * (i, j) covers [i, i + 1) x [j, j + 1). Returns nothing for a point behind the eye.
 * Needs no window or OpenGL context.
 */
std::optional<Vec2> projectToImage(const ViewCamera& camera, const Point3& world, int width,
                                   int height);

/// A view from just behind and above the scene camera, looking at its look-at point with
/// a slightly wider field of view: the rays leave the camera towards the viewer's scene
/// (`raylab trace --view camera`).
ViewCamera behindCameraView(const Scene& scene, double aspect);
/// A close view of object `index`: from the side of the scene camera (and a little above),
/// looking at the centre of the object's bounds from just far enough that the sphere
/// around them fills about 80% of the picture's height or width, whichever is smaller.
/// For an unbounded object (a plane), the default view.
ViewCamera closeUpView(const Scene& scene, int index, double aspect);
/**
 * \brief A close view of the hit where ray `id` of `tree` bends: the point it starts from
 * (for the camera ray, its own hit), looked at square to the plane of the incoming ray and
 * the outgoing one (for a camera ray, its first child; without one, the normal), so both
 * rays and the normal there lie in the picture and their angles can be read (Snell's law,
 * total internal reflection). Seen from the side of that plane the scene camera looks from
 * (its own rays lie in the plane); the sphere around the object hit there fills about 80% of
 * the picture. Without such a hit (an escaped camera ray, an id out of range), the default
 * view.
 */
ViewCamera closeUpOnRay(const Scene& scene, const RayTree& tree, int id, double aspect);

}  // namespace raylab::vis
