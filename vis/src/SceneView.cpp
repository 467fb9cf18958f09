#include "raylab/vis/SceneView.h"

#include "BvhActors.h"
#include "ExportRole.h"
#include "RayTreeActors.h"
#include "SceneViewImpl.h"
#include "ShapeGeometry.h"
#include "TeachingOverlays.h"
#include "TextFonts.h"
#include "VtkImage.h"

#include "raylab/core/Check.h"
#include "raylab/core/Phrases.h"
#include "raylab/core/Plane.h"
#include "raylab/core/SceneIntersector.h"
#include "raylab/core/Shape.h"
#include "raylab/core/Sphere.h"
#include "raylab/vis/Display.h"
#include "raylab/vis/ImageIO.h"

#include <vtkActor.h>
#include <vtkBox.h>
#include <vtkCamera.h>
#include <vtkClipPolyData.h>
#include <vtkImageData.h>
#include <vtkMapper.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataSilhouette.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace raylab::vis {

namespace {

/// Background of the 3D view: a dark slate that none of the scene colours uses.
/// Colour of the selection outline.
constexpr double kHighlight[3] = {1.0, 0.85, 0.0};
/// Colour and opacity of the scene camera's body, colour of its frustum lines: the lime of
/// camera rays (kindColour), never the light grey that means "no energy" on rays; the
/// frustum a darker lime in thin lines, so that a camera ray inside it stands out.
constexpr double kCameraBody[3] = {0.75, 0.95, 0.65};
constexpr double kCameraBodyOpacity = 0.45;
constexpr double kFrustum[3] = {0.33, 0.52, 0.22};
constexpr double kFrustumLineWidth = 1.0;
/// Colour of a point light's glyph: the original course program's flesh-coloured light.
constexpr double kPointLight[3] = {1.0, 0.8, 0.65};

/// The part of `geometry` inside `box`.
vtkSmartPointer<vtkPolyData> clipToBox(vtkPolyData* geometry, const Bounds3& box) {
  vtkNew<vtkBox> region;
  region->SetBounds(box.lower.x, box.upper.x, box.lower.y, box.upper.y, box.lower.z, box.upper.z);
  vtkNew<vtkClipPolyData> clip;
  clip->SetInputData(geometry);
  clip->SetClipFunction(region);
  clip->InsideOutOn();
  clip->Update();
  return clip->GetOutput();
}

/// Display colour of a material: emitters show their emission's hue at full brightness,
/// everything else its reflectance, clamped to [0, 1].
Vec3 displayColour(const Material& material) {
  if (material.isEmitter()) {
    const Vec3 e = glm::max(material.emission, Vec3(0.0));
    const double peak = std::max({e.x, e.y, e.z});
    return e / peak;
  }
  return glm::clamp(material.colour, Vec3(0.0), Vec3(1.0));
}

vtkSmartPointer<vtkActor> makeActor(vtkPolyData* geometry) {
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(geometry);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

/// The actor of one object's surface: its material's display colour and opacity, lit
/// (emitters unlit), curved surfaces smooth-shaded; `wall` is an enclosing wall's patch.
vtkSmartPointer<vtkActor> surfaceActor(vtkPolyData* geometry, const Material& material,
                                       ShapeKind kind, bool wall) {
  const Vec3 colour = displayColour(material);
  auto actor = makeActor(geometry);
  vtkProperty* p = actor->GetProperty();
  p->SetColor(colour.x, colour.y, colour.z);
  p->SetOpacity(std::clamp(material.opacity, 0.0, 1.0));
  if (material.isEmitter()) {
    p->LightingOff();
  } else {
    p->SetAmbient(0.25);
    p->SetDiffuse(0.8);
    const bool curved = (kind == ShapeKind::Sphere && !wall) || kind == ShapeKind::TriangleMesh;
    p->SetSpecular(curved ? 0.2 : 0.0);
    p->SetSpecularPower(30.0);
    if (curved)
      p->SetInterpolationToPhong();
    else
      p->SetInterpolationToFlat();
  }
  return actor;
}

/// The hidden selection outline of an object: its silhouette seen from `camera`
/// (recomputed when the camera moves), plus border edges (quads, and boxes whose faces
/// share no points) and creases sharper than 60 degrees.
vtkSmartPointer<vtkActor> outlineActor(vtkPolyData* geometry, vtkCamera* camera) {
  vtkNew<vtkPolyDataSilhouette> silhouette;
  silhouette->SetInputData(geometry);
  silhouette->SetCamera(camera);
  silhouette->SetDirectionToCameraOrigin();
  silhouette->BorderEdgesOn();
  silhouette->SetEnableFeatureAngle(1);
  silhouette->SetFeatureAngle(60.0);
  vtkNew<vtkPolyDataMapper> outlineMapper;
  outlineMapper->SetInputConnection(silhouette->GetOutputPort());
  outlineMapper->ScalarVisibilityOff();
  // Pull the outline well in front of its own surface: a silhouette lies exactly on
  // the rim, where half of a thick line would otherwise sink into the object.
  outlineMapper->SetRelativeCoincidentTopologyLineOffsetParameters(-4.0, -40.0);
  auto outline = vtkSmartPointer<vtkActor>::New();
  outline->SetMapper(outlineMapper);
  vtkProperty* c = outline->GetProperty();
  c->SetColor(kHighlight[0], kHighlight[1], kHighlight[2]);
  c->SetLineWidth(4.0);
  c->LightingOff();
  outline->VisibilityOff();
  return outline;
}

/// The scene camera as a translucent body with its frustum, and the point lights (the
/// classic algorithms' lights) as small flesh-coloured balls.
void addCameraAndLights(const Scene& scene, vtkRenderer* renderer) {
  auto body = makeActor(cameraBodyGeometry(scene.camera, cameraGlyphSize(scene)));
  body->GetProperty()->SetColor(kCameraBody[0], kCameraBody[1], kCameraBody[2]);
  body->GetProperty()->SetOpacity(kCameraBodyOpacity);
  body->GetProperty()->SetInterpolationToFlat();
  setExportRole(body, "camera");
  renderer->AddActor(body);
  auto frustum = makeActor(
      cameraFrustumGeometry(scene.camera, kFrustumLengthInGlyphs * cameraGlyphSize(scene)));
  frustum->GetProperty()->SetColor(kFrustum[0], kFrustum[1], kFrustum[2]);
  frustum->GetProperty()->SetLineWidth(kFrustumLineWidth);
  frustum->GetProperty()->LightingOff();
  setExportRole(frustum, "camera");
  renderer->AddActor(frustum);

  for (const PointLight& light : scene.pointLights) {
    vtkNew<vtkSphereSource> ball;
    ball->SetCenter(light.position.x, light.position.y, light.position.z);
    ball->SetRadius(0.3 * cameraGlyphSize(scene));
    ball->SetThetaResolution(16);
    ball->SetPhiResolution(12);
    ball->Update();
    auto glyph = makeActor(ball->GetOutput());
    glyph->GetProperty()->SetColor(kPointLight[0], kPointLight[1], kPointLight[2]);
    glyph->GetProperty()->LightingOff();
    setExportRole(glyph, "light");
    renderer->AddActor(glyph);
  }
}

/// Opacity of glass while a ray tree is shown, so the rays inside it can be followed.
constexpr double kGlassOpacityWithRays = 0.3;
/// Opacity of a mesh while its BVH is drawn, so the boxes inside it show.
constexpr double kMeshOpacityWithBoxes = 0.35;

/// Glass (dielectrics, and mirrors that refract) is drawn see-through while a ray tree is
/// shown (`rays` true), at the material's own opacity otherwise.
void seeThroughGlass(const Scene& scene, const std::vector<vtkSmartPointer<vtkActor>>& actors,
                     bool rays) {
  for (std::size_t i = 0; i < actors.size() && i < scene.objects.size(); ++i) {
    const int index = scene.objects[i].material;
    if (index < 0 || index >= int(scene.materials.size())) continue;
    const Material& m = scene.materials[std::size_t(index)];
    const bool glass = m.type == MaterialType::Dielectric ||
                       (m.type == MaterialType::Mirror && m.refractionRate > 0.0);
    const double opacity = std::clamp(m.opacity, 0.0, 1.0);
    actors[i]->GetProperty()->SetOpacity(glass && rays ? std::min(opacity, kGlassOpacityWithRays)
                                                       : opacity);
  }
}

}  // namespace

SceneView::SceneView(const Scene& scene) : m_impl(std::make_unique<Impl>()) {
  // Lines drawn over faces (the selection outline) are pulled towards the eye.
  vtkMapper::SetResolveCoincidentTopologyToPolygonOffset();
  m_impl->renderer->SetBackground(kBackground[0], kBackground[1], kBackground[2]);
  m_impl->bvh.background = Vec3(kBackground[0], kBackground[1], kBackground[2]);
  setScene(scene);
}

SceneView::~SceneView() = default;

void SceneView::setScene(const Scene& scene) {
  m_scene = scene;
  m_highlighted = -1;
  m_impl->bvh.build(m_scene, BvhStyle{});
  vtkRenderer* renderer = m_impl->renderer;
  renderer->RemoveAllViewProps();
  m_impl->objects.clear();
  m_impl->highlights.clear();
  m_impl->oneSided.clear();

  // Step 1: where the room is and how large the stand-in for an infinite plane must be.
  const Bounds3 box = drawnBounds(m_scene);
  DrawingFrame frame;
  frame.inside = box.centre();
  frame.planeHalfSize = std::max(1.5 * glm::length(box.extent()), 1.0);

  // Walls made of huge spheres (smallpt's) are drawn as patches around the room.
  const std::vector<bool> walls = enclosingWalls(m_scene);
  const bool anyWall = std::find(walls.begin(), walls.end(), true) != walls.end();
  const Bounds3 room = anyWall ? roomBounds(m_scene) : Bounds3();
  const bool hasWalls = anyWall && !room.empty();
  if (hasWalls) frame.inside = room.centre();
  // The box everything is clipped to: the room, a little larger.
  Bounds3 roomBox = room;
  if (hasWalls) {
    const Vec3 pad = 0.02 * room.extent() + Vec3(1e-9);
    roomBox = Bounds3(room.lower - pad, room.upper + pad);
  }
  m_impl->inside = frame.inside;

  // Step 2: one actor per object, coloured by its material, and its hidden outline.
  for (std::size_t index = 0; index < m_scene.objects.size(); ++index) {
    const SceneObject& object = m_scene.objects[index];
    RAYLAB_CHECK(object.shape != nullptr);
    const bool wall = walls[index];
    vtkSmartPointer<vtkPolyData> geometry =
        wall ? wallPatchGeometry(static_cast<const Sphere&>(*object.shape), frame,
                                 0.75 * glm::length(room.extent()))
             : shapeGeometry(*object.shape, frame);
    // Inside walls, only the room is drawn: smallpt's light, a sphere of radius 600 over
    // a room of 100, would otherwise hide it.
    if (hasWalls) geometry = clipToBox(geometry, roomBox);
    const bool known =
        object.material >= 0 && object.material < static_cast<int>(m_scene.materials.size());
    const Material material =
        known ? m_scene.materials[static_cast<std::size_t>(object.material)] : Material{};
    auto actor = surfaceActor(geometry, material, object.shape->kind(), wall);
    // Emitters stay two-sided: a ceiling light faces the room, yet must show from above.
    const bool oneSided = (object.shape->isFlat() || wall) && !material.isEmitter();
    if (oneSided) actor->GetProperty()->BackfaceCullingOn();
    m_impl->oneSided.push_back(oneSided);
    setExportRole(actor, "object:" + std::to_string(index));
    renderer->AddActor(actor);
    m_impl->objects.push_back(actor);

    const vtkSmartPointer<vtkActor> outline = outlineActor(geometry, renderer->GetActiveCamera());
    setExportRole(outline, "outline");
    renderer->AddActor(outline);
    m_impl->highlights.push_back(outline);
  }

  // Step 3: the scene camera (a translucent body and its frustum) and the point lights.
  addCameraAndLights(m_scene, renderer);

  // Step 4: the ray tree (kept across scene changes: re-trace and setRayTree to update).
  // Normals as long as the camera glyph is wide: at half that they were ticks hard to find.
  m_impl->rays.glyphLength = cameraGlyphSize(m_scene);
  m_impl->rays.addTo(renderer);
  m_impl->rays.markDirty();
  for (const auto& prop : m_impl->crossings) renderer->AddViewProp(prop);
  m_impl->bvh.addTo(renderer);
  applyOpacities();
  if (m_impl->caption) renderer->AddViewProp(m_impl->caption);

  // Step 5: look at it all from outside (or at the sample cloud, which replaces it all).
  resetViewCamera();
  if (!m_impl->cloud.empty()) showOnlyCloud();
}

void SceneView::showOnlyCloud() {
  vtkRenderer* renderer = m_impl->renderer;
  renderer->RemoveAllViewProps();
  for (const auto& prop : m_impl->cloud) renderer->AddViewProp(prop);
  ViewCamera view;
  view.eye = Point3(2.9, -3.3, 2.1);
  view.focalPoint = Point3(0.0, 0.0, 0.35);
  view.up = Vec3(0.0, 0.0, 1.0);
  view.viewAngle = 30.0;
  setViewCamera(view);
}

void SceneView::setCrossings(const std::vector<SceneCrossing>& crossings, const Point3& origin,
                             const Vec3& direction) {
  clearCrossings();
  m_impl->crossings = crossingProps(crossings, origin, direction, 0.6 * m_impl->rays.glyphLength);
  for (const auto& prop : m_impl->crossings) setExportRole(prop, "crossings");
  m_impl->crossingCount = int(crossings.size());
  for (const SceneCrossing& c : crossings)
    if (c.closed) m_impl->crossed.push_back(c.object);
  if (m_impl->cloud.empty())
    for (const auto& prop : m_impl->crossings) m_impl->renderer->AddViewProp(prop);
  seeThroughCrossed();
}

void SceneView::clearCrossings() {
  for (const auto& prop : m_impl->crossings) m_impl->renderer->RemoveViewProp(prop);
  m_impl->crossings.clear();
  m_impl->crossingCount = 0;
  m_impl->crossed.clear();
  applyOpacities();
}

void SceneView::seeThroughCrossed() {
  // The marks inside a solid show through it, as glass does while rays are drawn.
  for (int i : m_impl->crossed)
    if (i >= 0 && i < int(m_impl->objects.size())) {
      vtkProperty* p = m_impl->objects[std::size_t(i)]->GetProperty();
      p->SetOpacity(std::min(p->GetOpacity(), kGlassOpacityWithRays));
    }
}

int SceneView::crossingCount() const { return m_impl->crossingCount; }

void SceneView::setSampleCloud(const std::vector<Vec3>& directions, bool fullSphere,
                               const std::string& axisLabel, Language language) {
  m_impl->cloud = sampleCloudProps(directions, fullSphere, axisLabel, language);
  for (const auto& prop : m_impl->cloud) setExportRole(prop, "samples");
  showOnlyCloud();
}

void SceneView::clearSampleCloud() {
  if (m_impl->cloud.empty()) return;
  m_impl->cloud.clear();
  const int highlighted = m_highlighted;
  setScene(Scene(m_scene));  // the scene's props again, seen from the default view
  setHighlighted(highlighted);
}

bool SceneView::showsSampleCloud() const { return !m_impl->cloud.empty(); }

std::string sampleAxisLabel(LessonSamples::Sampler sampler, Language language) {
  return phrase(
      sampler == LessonSamples::Sampler::Phong ? "sample_axis.mirror" : "sample_axis.normal",
      language);
}

void SceneView::setCaption(const std::string& text, Language language) {
  if (m_impl->caption) m_impl->renderer->RemoveViewProp(m_impl->caption);
  m_impl->caption = nullptr;
  if (text.empty()) return;
  auto caption = vtkSmartPointer<vtkTextActor>::New();
  caption->SetInput(text.c_str());
  vtkTextProperty* p = caption->GetTextProperty();
  useFontFor(p, language);
  p->SetColor(0.95, 0.95, 0.95);
  p->SetBackgroundColor(0.0, 0.0, 0.0);
  p->SetBackgroundOpacity(0.65);
  p->SetFrame(false);
  caption->SetDisplayPosition(8, 8);
  m_impl->caption = caption;
  m_impl->renderer->AddViewProp(caption);
}

void SceneView::updateScene(const Scene& scene) {
  const ViewCamera camera = viewCamera();
  const int highlighted = m_highlighted;
  // The BVH boxes stay with their mesh (by name) when it is still there.
  const BvhStyle bvh = m_impl->bvh.style;
  const std::string bvhMesh = bvh.shown() && bvh.object < objectCount()
                                  ? m_scene.objects[std::size_t(bvh.object)].name
                                  : std::string();
  setScene(scene);
  setViewCamera(camera);
  setHighlighted(highlighted < objectCount() ? highlighted : -1);
  if (!bvhMesh.empty() && bvh.object < objectCount() &&
      m_scene.objects[std::size_t(bvh.object)].name == bvhMesh)
    setBvh(bvh);
}

void SceneView::setBvh(const BvhStyle& style) {
  m_impl->bvh.build(m_scene, style);
  applyOpacities();
}

void SceneView::clearBvh() { setBvh(BvhStyle{}); }

const BvhStyle& SceneView::bvhStyle() const { return m_impl->bvh.style; }

const BvhSummary& SceneView::bvhSummary() const { return m_impl->bvh.summary; }

void SceneView::applyOpacities() {
  seeThroughGlass(m_scene, m_impl->objects, m_impl->rays.shown);
  seeThroughCrossed();
  const int mesh = m_impl->bvh.summary.boxes > 0 ? m_impl->bvh.style.object : -1;
  if (mesh >= 0 && mesh < static_cast<int>(m_impl->objects.size())) {
    vtkProperty* p = m_impl->objects[static_cast<std::size_t>(mesh)]->GetProperty();
    p->SetOpacity(std::min(p->GetOpacity(), kMeshOpacityWithBoxes));
  }
}

Point3 SceneView::objectCentre(int index) const {
  RAYLAB_CHECK(index >= 0 && index < objectCount());
  const Shape& shape = *m_scene.objects[static_cast<std::size_t>(index)].shape;
  const Bounds3 b = shape.bounds();
  const Vec3 e = b.extent();
  if (shape.kind() == ShapeKind::Plane || b.empty() || !std::isfinite(e.x) || !std::isfinite(e.y) ||
      !std::isfinite(e.z)) {
    // Unbounded (a plane): the point of it nearest the middle of the room.
    const Point3 c = drawnBounds(m_scene).centre();
    if (shape.kind() != ShapeKind::Plane) return c;
    const auto& plane = static_cast<const Plane&>(shape);
    const Normal3 n = glm::normalize(plane.planeNormal());
    return c - glm::dot(c - plane.point(), n) * n;
  }
  return b.centre();
}

void SceneView::setHighlighted(int index) {
  if (index < 0 || index >= objectCount()) index = -1;
  for (std::size_t i = 0; i < m_impl->highlights.size(); ++i) {
    m_impl->highlights[i]->SetVisibility(static_cast<int>(i) == index);
  }
  m_highlighted = index;
}

ViewCamera SceneView::viewCamera() const {
  vtkCamera* c = m_impl->renderer->GetActiveCamera();
  ViewCamera view;
  double v[3];
  c->GetPosition(v);
  view.eye = Point3(v[0], v[1], v[2]);
  c->GetFocalPoint(v);
  view.focalPoint = Point3(v[0], v[1], v[2]);
  c->GetViewUp(v);
  view.up = Vec3(v[0], v[1], v[2]);
  view.viewAngle = c->GetViewAngle();
  return view;
}

void SceneView::setViewCamera(const ViewCamera& view) {
  vtkCamera* c = m_impl->renderer->GetActiveCamera();
  c->SetPosition(view.eye.x, view.eye.y, view.eye.z);
  c->SetFocalPoint(view.focalPoint.x, view.focalPoint.y, view.focalPoint.z);
  c->SetViewUp(view.up.x, view.up.y, view.up.z);
  c->SetViewAngle(view.viewAngle);
  c->OrthogonalizeViewUp();
  m_impl->renderer->ResetCameraClippingRange();
}

void SceneView::resetViewCamera(double aspect) {
  update();
  setViewCamera(defaultViewCamera(m_scene, aspect));
}

vtkRenderer* SceneView::renderer() const { return m_impl->renderer; }

void SceneView::update() { m_impl->rays.ensureBuilt(); }

SrgbImage SceneView::renderOffscreen(int width, int height) {
  RAYLAB_CHECK(width > 0 && height > 0);
  requireDisplay();
  update();
  vtkRenderer* renderer = m_impl->renderer;
  // The renderer can live in one window only: not while a widget shows it.
  RAYLAB_CHECK(renderer->GetRenderWindow() == nullptr ||
               renderer->GetRenderWindow() == m_impl->offscreen.Get());

  // Step 1: our own offscreen window, no multisampling (repeatable pixels).
  if (!m_impl->offscreen) {
    m_impl->offscreen = vtkSmartPointer<vtkRenderWindow>::New();
    RAYLAB_CHECK(m_impl->offscreen != nullptr);
    m_impl->offscreen->SetOffScreenRendering(1);
    m_impl->offscreen->SetMultiSamples(0);
    m_impl->offscreen->AddRenderer(renderer);
    // A new window lays text (the ray-tree legend) out differently in its very first
    // frame; render that one for nothing, so every picture is the same as the next.
    m_impl->offscreen->SetSize(width, height);
    m_impl->offscreen->Render();
  }
  m_impl->offscreen->SetSize(width, height);

  // The caption's size follows the picture's height (28 lines of it would fill it), and
  // shrinks to fit its width (a glyph is about 0.55 of the font size wide).
  if (m_impl->caption) {
    const double chars = std::max<double>(1.0, std::strlen(m_impl->caption->GetInput()));
    const int fit = int(std::floor((width - 16) / (0.55 * chars)));
    m_impl->caption->GetTextProperty()->SetFontSize(std::max(7, std::min(height / 28, fit)));
  }

  // Step 2: render, then read the back buffer.
  renderer->ResetCameraClippingRange();
  m_impl->offscreen->Render();
  return detail::grabWindow(m_impl->offscreen, width, height);
}

void SceneView::renderToPng(const std::string& path, int width, int height) {
  writePng(renderOffscreen(width, height), path);
}

void SceneView::setRayTree(const RayTree& tree, const RayTreeStyle& style) {
  setRayTree(std::make_shared<const RayTree>(tree), style);
}

void SceneView::setRayTree(std::shared_ptr<const RayTree> tree, const RayTreeStyle& style) {
  RayTreeActors& rays = m_impl->rays;
  rays.tree = std::move(tree);
  rays.style = style;
  rays.reaches = reachesLight(rays.drawnTree());
  rays.fraction.clear();
  rays.selected = -1;
  rays.shown = rays.tree != nullptr;
  rays.markDirty();
  applyOpacities();
}

void SceneView::clearRayTree() { setRayTree(std::shared_ptr<const RayTree>(), m_impl->rays.style); }

bool SceneView::hasRayTree() const { return m_impl->rays.shown; }

const RayTree& SceneView::rayTree() const { return m_impl->rays.drawnTree(); }

void SceneView::setRayTreeStyle(const RayTreeStyle& style) {
  m_impl->rays.style = style;
  m_impl->rays.markDirty();
}

const RayTreeStyle& SceneView::rayTreeStyle() const { return m_impl->rays.style; }

void SceneView::setReveal(const RevealFrame& frame) {
  RayTreeActors& rays = m_impl->rays;
  RAYLAB_CHECK_EQ(frame.fraction.size(), rays.drawnTree().segments.size());
  rays.fraction = frame.fraction;
  rays.markDirty();
}

void SceneView::revealAll() {
  m_impl->rays.fraction.clear();
  m_impl->rays.markDirty();
}

void SceneView::setSelectedSegment(int id) {
  RayTreeActors& rays = m_impl->rays;
  rays.selected = id >= 0 && id < int(rays.drawnTree().segments.size()) ? id : -1;
  rays.markDirty();
}

int SceneView::selectedSegment() const { return m_impl->rays.selected; }

int SceneView::rayTreeBuildCount() const { return m_impl->rays.buildCount(); }

std::optional<Vec2> SceneView::worldToImage(const Point3& world, int width, int height) const {
  return projectToImage(viewCamera(), world, width, height);
}

}  // namespace raylab::vis
