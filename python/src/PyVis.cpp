// VTK from Python: a ray tree and a scene as vtkPolyData built by vis (handed to Debian's
// python3-vtk9 in the same process by address), and the 3D view rendered offscreen.

#include "Bindings.h"

#include "RayTreeGeometry.h"
#include "ShapeGeometry.h"

#include "raylab/core/Sphere.h"
#include "raylab/vis/ImageIO.h"
#include "raylab/vis/RayTreeStyle.h"
#include "raylab/vis/SceneView.h"
#include "raylab/vis/TreeViewState.h"
#include "raylab/vis/ViewCamera.h"

#include <pybind11/stl.h>

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <vector>

namespace raylab::python {
namespace {

/**
 * \brief A vtkPolyData made in C++, waiting to be wrapped by VTK's Python package.
 *
 * VTK's Python wrappers make an object from a "pointer string" of the form
 * `_<hex address>_p_vtkPolyData` (vtkPythonUtil::UnmanglePointer): `vtkPolyData(address)`.
 * The wrapper takes its own reference; this holder keeps one until it is dropped, so the
 * address is valid for as long as the holder lives. raylab/_vtk.py does the wrapping.
 */
struct PolyDataHolder {
  vtkSmartPointer<vtkPolyData> data;

  std::string address() const {
    char text[64];
    std::snprintf(text, sizeof text, "_%0*llx_p_vtkPolyData", int(2 * sizeof(void*)),
                  static_cast<unsigned long long>(reinterpret_cast<std::uintptr_t>(data.Get())));
    return text;
  }
};

/// The colouring of a plain trace's tree. "verdict" is refused: a plain trace has no
/// verdicts (every ray would be grey); a student's judged trace draws them.
vis::RayColouring colouringNamed(const std::string& name) {
  if (name == "verdict")
    throw py::value_error(
        "colouring 'verdict' needs a trace judged against a student's code: use "
        "raylab.student.trace(...) and raylab.student.save_view(...), or raylab check; a plain "
        "trace's colourings are energy, kind and depth");
  if (std::optional<vis::RayColouring> c = vis::parseColouring(name)) return *c;
  throw py::value_error("unknown colouring '" + name +
                        "': use energy, kind or depth (verdict: a student's judged trace, "
                        "raylab.student.save_view)");
}

template <typename Array>
vtkSmartPointer<Array> cellArray(const char* name, int components, vtkIdType cells) {
  auto array = vtkSmartPointer<Array>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(cells);
  return array;
}

/// Every ray of the tree as one line cell (origin to end point), coloured as the 3D view
/// colours it, with the segment's id, energy, depth and kind as cell data.
PolyDataHolder treePolyData(const TraceData& data, const std::string& colouring) {
  vis::RayTreeStyle style;
  style.colouring = colouringNamed(colouring);
  style.widthFollowsEnergy = false;  // one width class: every ray in lines[0]
  style.showHitPoints = false;
  const RayTree& tree = data.trace.tree;
  const vis::RayTreeGeometry geometry =
      vis::buildRayTreeGeometry(tree, style, vis::reachesLight(tree), nullptr, 1.0, Vec3(0.0));
  vtkSmartPointer<vtkPolyData> lines = geometry.lines[0];
  const std::vector<int>& ids = geometry.cellSegment[0];
  const vtkIdType cells = vtkIdType(ids.size());
  auto segment = cellArray<vtkIntArray>("segment", 1, cells);
  auto depth = cellArray<vtkIntArray>("depth", 1, cells);
  auto kind = cellArray<vtkIntArray>("kind", 1, cells);
  auto energy = cellArray<vtkDoubleArray>("energy", 1, cells);
  for (vtkIdType c = 0; c < cells; ++c) {
    const RaySegment& s = tree.segments[std::size_t(ids[std::size_t(c)])];
    segment->SetValue(c, s.id);
    depth->SetValue(c, s.depth);
    kind->SetValue(c, int(s.kind));
    energy->SetValue(c, s.energy());
  }
  vtkCellData* cd = lines->GetCellData();
  cd->AddArray(segment);
  cd->AddArray(depth);
  cd->AddArray(kind);
  cd->AddArray(energy);
  return {lines};
}

/// Every object's surface, as the 3D view draws it (vis's shape geometry), in one polydata
/// with the object's index and its material's colour (8-bit, linear shown as is) per cell.
PolyDataHolder scenePolyData(const Scene& scene) {
  const Bounds3 box = vis::drawnBounds(scene);
  vis::DrawingFrame frame;
  frame.inside = box.centre();
  frame.planeHalfSize = std::max(1.5 * glm::length(box.extent()), 1.0);
  const std::vector<bool> walls = vis::enclosingWalls(scene);
  const Bounds3 room = vis::roomBounds(scene);
  if (std::find(walls.begin(), walls.end(), true) != walls.end() && !room.empty())
    frame.inside = room.centre();

  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  auto object = vtkSmartPointer<vtkIntArray>::New();
  object->SetName("object");
  auto colour = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colour->SetName("colour");
  colour->SetNumberOfComponents(3);
  for (std::size_t index = 0; index < scene.objects.size(); ++index) {
    const SceneObject& o = scene.objects[index];
    const vtkSmartPointer<vtkPolyData> part =
        walls[index] ? vis::wallPatchGeometry(static_cast<const Sphere&>(*o.shape), frame,
                                              0.75 * glm::length(room.extent()))
                     : vis::shapeGeometry(*o.shape, frame);
    const Vec3 c = o.material >= 0 && o.material < int(scene.materials.size())
                       ? scene.materials[std::size_t(o.material)].colour
                       : Vec3(0.8);
    const vtkIdType offset = points->GetNumberOfPoints();
    for (vtkIdType p = 0; p < part->GetNumberOfPoints(); ++p)
      points->InsertNextPoint(part->GetPoint(p));
    vtkCellArray* source = part->GetPolys();
    source->InitTraversal();
    vtkIdType count = 0;
    const vtkIdType* cellPoints = nullptr;
    std::vector<vtkIdType> shifted;
    while (source->GetNextCell(count, cellPoints)) {
      shifted.assign(cellPoints, cellPoints + count);
      for (vtkIdType& id : shifted) id += offset;
      polys->InsertNextCell(count, shifted.data());
      object->InsertNextValue(int(index));
      colour->InsertNextTuple3(255.0 * std::clamp(c.x, 0.0, 1.0), 255.0 * std::clamp(c.y, 0.0, 1.0),
                               255.0 * std::clamp(c.z, 0.0, 1.0));
    }
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(points);
  out->SetPolys(polys);
  out->GetCellData()->AddArray(object);
  out->GetCellData()->AddArray(colour);
  return {out};
}

/// The 3D view of the scene (with a trace's tree) rendered offscreen.
SrgbImage renderView(const SceneHandle& scene, const std::shared_ptr<TraceData>& trace, int width,
                     int height, const std::string& colouring, const std::string& camera) {
  if (width < 1 || height < 1) throw py::value_error("width and height must be at least 1");
  if (camera != "default" && camera != "camera")
    throw py::value_error("unknown view '" + camera + "': use default or camera");
  vis::RayTreeStyle style;
  style.colouring = colouringNamed(colouring);
  const std::shared_ptr<const Scene> snapshot = scene.scene;
  py::gil_scoped_release release;
  // The view state the window and the handouts draw with (SceneView::show).
  vis::TreeViewState state;
  state.traced = trace != nullptr;
  state.style = style;
  state.camera = camera == "camera" ? vis::CameraChoice::BehindCamera : vis::CameraChoice::Default;
  vis::SceneView view(*snapshot);
  const std::shared_ptr<const RayTree> tree =
      trace ? std::shared_ptr<const RayTree>(trace, &trace->trace.tree) : nullptr;
  view.show(state, tree, double(width) / height);
  return view.renderOffscreen(width, height);
}

}  // namespace

void bindVis(py::module_& m) {
  py::class_<PolyDataHolder>(m, "_PolyDataHolder")
      .def_property_readonly("address", &PolyDataHolder::address)
      .def_property_readonly("reference_count",
                             [](const PolyDataHolder& h) { return h.data->GetReferenceCount(); })
      .def_property_readonly("cells",
                             [](const PolyDataHolder& h) { return h.data->GetNumberOfCells(); });

  m.def("_tree_polydata", &treePolyData, py::arg("trace"), py::arg("colouring") = "energy");
  m.def(
      "_scene_polydata", [](const SceneHandle& h) { return scenePolyData(*h.scene); },
      py::arg("scene"));

  m.def(
      "view_image",
      [](const SceneHandle& scene, const std::shared_ptr<TraceData>& trace, int width, int height,
         const std::string& colouring, const std::string& camera) {
        const SrgbImage image = renderView(scene, trace, width, height, colouring, camera);
        py::array_t<std::uint8_t> out({image.height, image.width, 3});
        std::memcpy(out.mutable_data(), image.rgb.data(), image.rgb.size());
        return out;
      },
      py::arg("scene"), py::arg("trace") = nullptr, py::kw_only(), py::arg("width") = 300,
      py::arg("height") = 300, py::arg("colouring") = "energy", py::arg("view") = "default",
      R"(The 3D view (raylab snapshot / trace's picture) rendered offscreen: an H x W x 3 uint8
array, rows from the top. With a trace, its ray tree is drawn (colouring energy, kind or
depth). view='camera' looks from behind the scene camera. Needs an X server (xvfb-run).)");
  m.def(
      "save_view",
      [](const std::string& path, const SceneHandle& scene, const std::shared_ptr<TraceData>& trace,
         int width, int height, const std::string& colouring, const std::string& camera) {
        const SrgbImage image = renderView(scene, trace, width, height, colouring, camera);
        vis::writePng(image, path);
      },
      py::arg("path"), py::arg("scene"), py::arg("trace") = nullptr, py::kw_only(),
      py::arg("width") = 300, py::arg("height") = 300, py::arg("colouring") = "energy",
      py::arg("view") = "default", "view_image written as a PNG file.");
}

}  // namespace raylab::python
