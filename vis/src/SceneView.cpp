#include "raylab/vis/SceneView.h"

#include "ShapeGeometry.h"

#include "raylab/core/Check.h"
#include "raylab/core/Plane.h"
#include "raylab/core/Shape.h"
#include "raylab/vis/ImageIO.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkMapper.h>
#include <vtkNew.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataSilhouette.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace raylab {

namespace {

/// Background of the 3D view: a dark slate that none of the scene colours uses.
constexpr double kBackground[3] = {0.12, 0.13, 0.16};
/// Colour of the selection outline.
constexpr double kHighlight[3] = {1.0, 0.85, 0.0};
/// Colour and opacity of the scene camera's body, colour of its frustum lines.
constexpr double kCameraBody[3] = {0.85, 0.88, 0.95};
constexpr double kCameraBodyOpacity = 0.45;
constexpr double kFrustum[3] = {0.9, 0.9, 0.9};

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

}  // namespace

struct SceneView::Impl {
  vtkNew<vtkRenderer> renderer;
  std::vector<vtkSmartPointer<vtkActor>> objects;     ///< One per scene object.
  std::vector<vtkSmartPointer<vtkActor>> highlights;  ///< Hidden outlines, one per object.
  vtkSmartPointer<vtkRenderWindow> offscreen;         ///< Created on first offscreen render.

  ~Impl() {
    if (offscreen) {
      offscreen->RemoveRenderer(renderer);
      offscreen->Finalize();
    }
  }
};

SceneView::SceneView(const Scene& scene) : m_impl(std::make_unique<Impl>()) {
  // Lines drawn over faces (the selection outline) are pulled towards the eye.
  vtkMapper::SetResolveCoincidentTopologyToPolygonOffset();
  m_impl->renderer->SetBackground(kBackground[0], kBackground[1], kBackground[2]);
  setScene(scene);
}

SceneView::~SceneView() = default;

void SceneView::setScene(const Scene& scene) {
  m_scene = scene;
  m_highlighted = -1;
  vtkRenderer* renderer = m_impl->renderer;
  renderer->RemoveAllViewProps();
  m_impl->objects.clear();
  m_impl->highlights.clear();

  // Step 1: where the room is and how large the stand-in for an infinite plane must be.
  const Bounds3 box = drawnBounds(m_scene);
  DrawingFrame frame;
  frame.inside = box.centre();
  frame.planeHalfSize = std::max(1.5 * glm::length(box.extent()), 1.0);

  // Step 2: one actor per object, coloured by its material, and its hidden outline.
  for (const SceneObject& object : m_scene.objects) {
    RAYLAB_CHECK(object.shape != nullptr);
    const vtkSmartPointer<vtkPolyData> geometry = shapeGeometry(*object.shape, frame);
    const bool known =
        object.material >= 0 && object.material < static_cast<int>(m_scene.materials.size());
    const Material material =
        known ? m_scene.materials[static_cast<std::size_t>(object.material)] : Material{};
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
      const bool curved = object.shape->kind() == ShapeKind::Sphere ||
                          object.shape->kind() == ShapeKind::TriangleMesh;
      p->SetSpecular(curved ? 0.2 : 0.0);
      p->SetSpecularPower(30.0);
      if (curved)
        p->SetInterpolationToPhong();
      else
        p->SetInterpolationToFlat();
    }
    if (isOpenSurface(object.shape->kind())) p->BackfaceCullingOn();
    renderer->AddActor(actor);
    m_impl->objects.push_back(actor);

    // The selection outline: silhouette seen from the view camera (recomputed when the
    // camera moves), plus border edges (quads, and boxes whose faces share no points)
    // and creases sharper than 60 degrees.
    vtkNew<vtkPolyDataSilhouette> silhouette;
    silhouette->SetInputData(geometry);
    silhouette->SetCamera(renderer->GetActiveCamera());
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
    renderer->AddActor(outline);
    m_impl->highlights.push_back(outline);
  }

  // Step 3: the scene camera: a translucent body and its frustum.
  auto body = makeActor(cameraBodyGeometry(m_scene.camera, cameraGlyphSize(m_scene)));
  body->GetProperty()->SetColor(kCameraBody[0], kCameraBody[1], kCameraBody[2]);
  body->GetProperty()->SetOpacity(kCameraBodyOpacity);
  body->GetProperty()->SetInterpolationToFlat();
  renderer->AddActor(body);
  auto frustum = makeActor(
      cameraFrustumGeometry(m_scene.camera, kFrustumLengthInGlyphs * cameraGlyphSize(m_scene)));
  frustum->GetProperty()->SetColor(kFrustum[0], kFrustum[1], kFrustum[2]);
  frustum->GetProperty()->SetLineWidth(1.5);
  frustum->GetProperty()->LightingOff();
  renderer->AddActor(frustum);

  // Step 4: look at it all from outside.
  resetViewCamera();
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
  setViewCamera(defaultViewCamera(m_scene, aspect));
}

vtkRenderer* SceneView::renderer() const { return m_impl->renderer; }

Image SceneView::renderOffscreen(int width, int height) {
  RAYLAB_CHECK(width > 0 && height > 0);
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
  }
  m_impl->offscreen->SetSize(width, height);

  // Step 2: render, then read the back buffer.
  renderer->ResetCameraClippingRange();
  m_impl->offscreen->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(m_impl->offscreen);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOff();
  grab->Update();
  vtkImageData* data = grab->GetOutput();
  int dims[3] = {0, 0, 0};
  data->GetDimensions(dims);
  RAYLAB_CHECK_EQ(dims[0], width);
  RAYLAB_CHECK_EQ(dims[1], height);
  RAYLAB_CHECK_EQ(data->GetNumberOfScalarComponents(), 3);

  // Step 3: VTK's rows run bottom-up; ours top-down.
  Image image(width, height);
  const auto* in = static_cast<const std::uint8_t*>(data->GetScalarPointer());
  const std::size_t rowBytes = static_cast<std::size_t>(width) * 3;
  for (int y = 0; y < height; ++y) {
    std::memcpy(image.rgb.data() + static_cast<std::size_t>(y) * rowBytes,
                in + static_cast<std::size_t>(height - 1 - y) * rowBytes, rowBytes);
  }
  return image;
}

void SceneView::renderToPng(const std::string& path, int width, int height) {
  ImageIO::writePng(renderOffscreen(width, height), path);
}

std::optional<Vec2> SceneView::worldToImage(const Point3& world, int width, int height) const {
  return projectToImage(viewCamera(), world, width, height);
}

}  // namespace raylab
