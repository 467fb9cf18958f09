#include "TeachingOverlays.h"

#include "TextFonts.h"

#include <vtkActor.h>
#include <vtkArrowSource.h>
#include <vtkBillboardTextActor3D.h>
#include <vtkCellArray.h>
#include <vtkDiskSource.h>
#include <vtkLineSource.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkSphereSource.h>
#include <vtkTextProperty.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>

#include <algorithm>

namespace raylab::vis {

namespace {

vtkSmartPointer<vtkActor> actorOf(vtkPolyData* data, const double colour[3]) {
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(colour[0], colour[1], colour[2]);
  return actor;
}

vtkSmartPointer<vtkPolyData> ball(const Point3& centre, double radius) {
  vtkNew<vtkSphereSource> source;
  source->SetCenter(centre.x, centre.y, centre.z);
  source->SetRadius(radius);
  source->SetThetaResolution(20);
  source->SetPhiResolution(14);
  source->Update();
  return source->GetOutput();
}

}  // namespace

std::vector<vtkSmartPointer<vtkProp>> crossingProps(const std::vector<SceneCrossing>& crossings,
                                                    const Point3& origin, const Vec3& direction,
                                                    double markRadius) {
  std::vector<vtkSmartPointer<vtkProp>> props;
  const Vec3 unit = glm::normalize(direction);
  // The whole line: through every crossing and a little beyond the last.
  const double far = crossings.empty() ? 20.0 * markRadius : crossings.back().t + 8.0 * markRadius;
  vtkNew<vtkLineSource> line;
  const Point3 end = origin + far * unit;
  line->SetPoint1(origin.x, origin.y, origin.z);
  line->SetPoint2(end.x, end.y, end.z);
  line->Update();
  constexpr double kLine[3] = {0.85, 0.85, 0.9};
  auto lineActor = actorOf(line->GetOutput(), kLine);
  lineActor->GetProperty()->SetLineWidth(1.5);
  lineActor->GetProperty()->LightingOff();
  props.push_back(lineActor);
  for (const SceneCrossing& c : crossings) {
    const double* colour =
        !c.closed ? kOpenSurfaceColour : (c.entering ? kEnteringColour : kLeavingColour);
    auto mark = actorOf(ball(c.point, markRadius), colour);
    mark->GetProperty()->SetAmbient(0.35);
    props.push_back(mark);
  }
  return props;
}

std::vector<vtkSmartPointer<vtkProp>> sampleCloudProps(const std::vector<Vec3>& directions,
                                                       bool fullSphere,
                                                       const std::string& axisLabel,
                                                       Language language) {
  std::vector<vtkSmartPointer<vtkProp>> props;

  // The surface: a grey disk in the z = 0 plane, seen from above at an angle.
  vtkNew<vtkDiskSource> disk;
  disk->SetInnerRadius(0.0);
  disk->SetOuterRadius(1.0);
  disk->SetCircumferentialResolution(96);
  disk->Update();
  constexpr double kSurface[3] = {0.5, 0.55, 0.62};
  auto surface = actorOf(disk->GetOutput(), kSurface);
  surface->GetProperty()->SetOpacity(0.8);
  surface->GetProperty()->SetAmbient(0.4);
  props.push_back(surface);

  // The (hemi)sphere the directions end on, as a light wireframe.
  vtkNew<vtkSphereSource> dome;
  dome->SetRadius(1.0);
  dome->SetThetaResolution(24);
  dome->SetPhiResolution(fullSphere ? 12 : 6);
  dome->SetStartPhi(0.0);
  dome->SetEndPhi(fullSphere ? 180.0 : 90.0);
  dome->Update();
  constexpr double kDome[3] = {0.6, 0.65, 0.75};
  auto wire = actorOf(dome->GetOutput(), kDome);
  wire->GetProperty()->SetRepresentationToWireframe();
  wire->GetProperty()->SetOpacity(0.35);
  wire->GetProperty()->LightingOff();
  props.push_back(wire);

  // The normal: an arrow along +z.
  vtkNew<vtkArrowSource> arrow;
  arrow->SetTipLength(0.15);
  arrow->SetShaftRadius(0.012);
  arrow->SetTipRadius(0.04);
  vtkNew<vtkTransform> upright;
  upright->RotateY(-90.0);  // the arrow points along +x; turn it to +z
  upright->Scale(1.25, 1.25, 1.25);
  vtkNew<vtkTransformPolyDataFilter> turned;
  turned->SetInputConnection(arrow->GetOutputPort());
  turned->SetTransform(upright);
  turned->Update();
  constexpr double kNormal[3] = {0.95, 0.85, 0.2};
  props.push_back(actorOf(turned->GetOutput(), kNormal));
  // Its name at the tip: the normal, or the mirror direction a Phong lobe is drawn about.
  if (!axisLabel.empty()) {
    auto label = vtkSmartPointer<vtkBillboardTextActor3D>::New();
    label->SetInput(axisLabel.c_str());
    label->SetPosition(0.06, 0.0, 1.32);
    vtkTextProperty* text = label->GetTextProperty();
    useFontFor(text, language);
    text->SetFontSize(22);
    text->SetColor(kNormal[0], kNormal[1], kNormal[2]);
    text->SetJustificationToLeft();
    text->SetVerticalJustificationToBottom();
    props.push_back(label);
  }

  // The directions: one point each on the unit sphere.
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> vertices;
  for (const Vec3& d : directions) {
    const vtkIdType id = points->InsertNextPoint(d.x, d.y, d.z);
    vertices->InsertNextCell(1, &id);
  }
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(points);
  cloud->SetVerts(vertices);
  auto dots = actorOf(cloud, kSampleColour);
  dots->GetProperty()->SetPointSize(7.0);
  dots->GetProperty()->RenderPointsAsSpheresOn();
  props.push_back(dots);
  return props;
}

}  // namespace raylab::vis
