#pragma once

#include "raylab/core/Lesson.h"
#include "raylab/core/RayInspector.h"
#include "raylab/core/RayTree.h"
#include "raylab/core/Scene.h"
#include "raylab/core/Types.h"
#include "raylab/vis/BounceAnimation.h"
#include "raylab/vis/BvhStyle.h"
#include "raylab/vis/Image.h"
#include "raylab/vis/RayTreeStyle.h"
#include "raylab/vis/TreeViewState.h"
#include "raylab/vis/ViewCamera.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

class vtkRenderer;

namespace raylab::vis {

/**
 * \brief The 3D view of a scene: one VTK renderer holding an actor per scene object, the
 * scene camera's glyph (translucent body and frustum lines) and a view camera.
 *
 * This is the picture the teacher turns around in the window and that tests render
 * offscreen. Drawing rules:
 *  - each object takes its material's colour (linear RGB shown as is), lit by a headlight
 *    with some ambient light; emitters are drawn unlit in their emission colour scaled so
 *    its largest channel is 1 (the flesh-coloured light cube shows as ~(1.0, 0.8, 0.65));
 *  - boxes are flat-shaded hexahedra; spheres use the shape's m x n tessellation;
 *  - open surfaces (planes, quads, triangles) face the room and are drawn one-sided
 *    (back faces culled), so from outside one looks through the near walls into the room
 *    (a dollhouse cut-away); an infinite plane is drawn as a large finite square;
 *  - the selected object gets a pale orchid outline (selectionOutlineColour): its silhouette as
 * seen from the view camera, its border edges and its sharp creases, drawn over it in thick lines.
 *
 * The renderer can be shown in one render window at a time: either the app's widget
 * (take `renderer()`), or this class's own offscreen window (`renderOffscreen`).
 */
class SceneView {
 public:
  /// Builds the actors for `scene` and the default view camera (see defaultViewCamera).
  explicit SceneView(const Scene& scene);
  ~SceneView();
  SceneView(const SceneView&) = delete;
  SceneView& operator=(const SceneView&) = delete;

  /**
   * \brief Shows `state` (TreeViewState.h) over the scene: `tree` (the state's traced tree,
   * shared, never copied; null or `state.hidden` or not `state.traced`: no tree) drawn with
   * its style, revealed to its frame, its selected ray marked, every crossing of that ray
   * (or ray 0) with `allHits`, the BVH boxes, a sampler's directions in place of the scene
   * (Samples layout), the selected object outlined, and the view camera of `state` for a
   * picture of aspect `aspect` (width / height; the sample cloud keeps its own side view).
   * Replaces whatever these showed before.
   */
  void show(const TreeViewState& state, std::shared_ptr<const RayTree> tree, double aspect);

  /// Replaces every actor with those of `scene`, clears the selection, resets the view.
  void setScene(const Scene& scene);
  /// The same scene after an edit: replaces the actors but keeps the view camera (and the
  /// highlighted object when it still exists), so an edit does not move the teacher's view.
  void updateScene(const Scene& scene);
  /// The scene as last given to the view.
  const Scene& scene() const { return m_scene; }

  /// Number of scene objects; object i is Scene::objects[i].
  int objectCount() const { return static_cast<int>(m_scene.objects.size()); }
  /// World-space centre of object i (the centre of its bounds; a plane's reference point).
  Point3 objectCentre(int index) const;

  /// The object seen at image point (x, y) (pixels, y down) of a width x height picture of
  /// the current view: the first object the view ray through that point meets, traced by
  /// core's SceneIntersector (exact, no GL picking); -1 when it meets none.
  int objectAt(double x, double y, int width, int height) const;

  /// Highlights object `index` with an outline; -1 (or any index out of range) clears.
  void setHighlighted(int index);
  /// The highlighted object, or -1.
  int highlighted() const { return m_highlighted; }

  /// The view camera now (it moves when the user drags in the window).
  ViewCamera viewCamera() const;
  /// Moves the view camera.
  void setViewCamera(const ViewCamera& camera);
  /// Back to the default view for a picture of aspect ratio `aspect` (width / height).
  void resetViewCamera(double aspect = 1.0);

  /// \name The ray tree drawn in the view (one polydata, one actor for all its rays).
  /// The setters below only record what to draw; the polydata are built once, before the
  /// next render or pick, however many setters were called (rayTreeBuildCount counts).
  /// @{
  /// Shows `tree` (replacing any other) with `style`, wholly revealed; the view shares
  /// the tree, never copies it (null: no tree). The tree stays through setScene (trace
  /// again and call this to update it). While a tree is shown, glass (dielectric) objects
  /// are drawn see-through (opacity 0.3) so that the rays refracted and reflected inside
  /// them can be followed.
  void setRayTree(std::shared_ptr<const RayTree> tree, const RayTreeStyle& style = {});
  /// The same with a copy of `tree` (for one-off pictures).
  void setRayTree(const RayTree& tree, const RayTreeStyle& style = {});
  /// Removes the ray tree from the view.
  void clearRayTree();
  /// True when a tree is shown.
  bool hasRayTree() const;
  /// The tree shown (empty when none).
  const RayTree& rayTree() const;
  /// Redraws the tree with another style (colouring, filters, toggles).
  void setRayTreeStyle(const RayTreeStyle& style);
  const RayTreeStyle& rayTreeStyle() const;
  /// Shows the tree as in animation frame `frame` (see revealFrame).
  void setReveal(const RevealFrame& frame);
  /// Shows the whole tree again.
  void revealAll();
  /// Marks segment `id` (drawn thick, in magenta, as far as it is revealed); -1 clears.
  void setSelectedSegment(int id);
  int selectedSegment() const;
  /// How many times the tree's polydata have been built (for tests: one per render after
  /// any number of changes).
  int rayTreeBuildCount() const;
  /// The drawn segment nearest to image point (x, y) (pixels, y down) of a width x height
  /// picture of the current view, within `tolerance` pixels; -1 when none.
  int segmentAt(double x, double y, int width, int height, double tolerance = 6.0) const;
  /// @}

  /// \name Lesson overlays
  /// @{
  /// Marks every crossing along the ray `origin + t * direction` (sceneCrossings): the ray
  /// drawn on through all of them, a green ball where it enters a solid, red where it
  /// leaves, yellow where it crosses an open surface; the solids it passes through are
  /// drawn see-through. Kept until clearCrossings.
  void setCrossings(const std::vector<SceneCrossing>& crossings, const Point3& origin,
                    const Vec3& direction);
  void clearCrossings();
  /// Number of crossings marked (0 when none).
  int crossingCount() const;
  /// Shows only a sampler's unit directions (LessonSamples::directions) as a point cloud
  /// over a disk (the surface, normal +z drawn up), instead of the scene, seen from the
  /// side; `fullSphere` outlines the whole sphere; `axisLabel` names the axis the
  /// directions are drawn about (sampleAxisLabel), in `language`. clearSampleCloud brings
  /// the scene back.
  void setSampleCloud(const std::vector<Vec3>& directions, bool fullSphere = false,
                      const std::string& axisLabel = {}, Language language = Language::English);
  void clearSampleCloud();
  bool showsSampleCloud() const;
  /// A line of text along the bottom of the picture, on a dark band (the bounce
  /// animation's narration in `raylab animate`'s frames); empty removes it. Its size
  /// follows the picture's height.
  void setCaption(const std::string& text, Language language = Language::English);
  /// @}

  /// \name A mesh's bounding volume hierarchy drawn in the view (lesson 8; BvhStyle.h).
  /// It is drawn together with the ray tree, and kept through updateScene while the scene
  /// still has the mesh (an object of the same name at the same index); setScene clears
  /// it. Building the boxes happens in the setter.
  /// @{
  /// Draws the boxes `style` asks for (style.object -1, or an object that is not a mesh:
  /// none); while they are shown the mesh is see-through.
  void setBvh(const BvhStyle& style);
  /// Removes the boxes.
  void clearBvh();
  const BvhStyle& bvhStyle() const;
  /// What is drawn now, counted (for tests and captions).
  const BvhSummary& bvhSummary() const;
  /// @}

  /// The VTK renderer, for a window to show (at most one window at a time).
  vtkRenderer* renderer() const;
  /// Builds what changed since the last render (the ray tree's polydata). Offscreen
  /// renders and picks call it themselves; a widget showing renderer() calls it before
  /// each render (a render without it still builds, but after the clipping range is set).
  void update();

  /**
   * \brief Renders the view offscreen into a width x height image.
   *
   * Uses this view's own vtkRenderWindow with OffScreenRenderingOn and no multisampling,
   * so pictures are repeatable for baselines. Needs an X server (Debian's VTK opens its
   * GL context through GLX even offscreen; use xvfb-run). Must not be called while the
   * renderer is shown in another window (checked).
   */
  SrgbImage renderOffscreen(int width, int height);
  /// renderOffscreen, then vis::writePng (throws vis::ImageError naming the file).
  void renderToPng(const std::string& path, int width, int height);

  /// Where a world point appears in a width x height rendering of the current view, in
  /// image coordinates (x right, y down, pixels); nothing when it is behind the eye.
  std::optional<Vec2> worldToImage(const Point3& world, int width, int height) const;

 private:
  /// Puts only the sample cloud in the renderer and looks at it.
  void showOnlyCloud();
  /// Draws the solids the marked crossings pass through see-through.
  void seeThroughCrossed();
  /// Object opacities: glass see-through while rays are shown, the solids crossings pass
  /// through, a mesh while its BVH is drawn.
  void applyOpacities();

  struct Impl;
  std::unique_ptr<Impl> m_impl;
  Scene m_scene;
  int m_highlighted = -1;
};

/// The name of the axis a sampler's directions are drawn about, in `language`: the surface
/// normal, or for the Phong lobe the mirror direction (its disk is then square to the
/// mirror direction, not the surface).
std::string sampleAxisLabel(LessonSamples::Sampler sampler, Language language);

}  // namespace raylab::vis
