// The main window driven by synthetic Qt events: the object list, selection highlighting,
// the trackball camera (drag rotates, wheel zooms), and the ray-tree panel (trace a pixel,
// filters, the bounce animation, clicking a ray into the inspector). Needs an X display
// with GLX (QVTKOpenGLNativeWidget needs real OpenGL): runs under xvfb with xcb.
#include "WindowTest.h"

#include "raylab/core/InspectorWords.h"

#include <QMenuBar>

namespace raylab::app {
namespace {

using namespace raylab::vis;

using MainWindowTest = WindowTest;

TEST_F(MainWindowTest, 01_ListsTheObjectsAndNamesTheScene) {
  const Scene scene = defaultScene();
  QListWidget* list = m_window->objectList();
  ASSERT_EQ(list->count(), static_cast<int>(scene.objects.size()));
  for (int i = 0; i < list->count(); ++i) {
    EXPECT_EQ(list->item(i)->text().toStdString(), scene.objects[static_cast<std::size_t>(i)].name);
  }
  EXPECT_TRUE(m_window->windowTitle().contains(QString::fromStdString(scene.name)));
}

TEST_F(MainWindowTest, 02_SelectingInTheListHighlightsInTheView) {
  const int sphere = defaultScene().findObject("red sphere");
  EXPECT_EQ(m_window->sceneView().highlighted(), -1);
  m_window->objectList()->setCurrentRow(sphere);  // as a click on the item does
  settle();
  EXPECT_EQ(m_window->sceneView().highlighted(), sphere);
  m_window->objectList()->setCurrentRow(sphere + 1);
  settle();
  EXPECT_EQ(m_window->sceneView().highlighted(), sphere + 1);
}

TEST_F(MainWindowTest, 03_DragRotatesTheViewAroundTheRoom) {
  const ViewCamera before = m_window->sceneView().viewCamera();
  const QPoint middle = m_window->viewWidget()->rect().center();
  drag(middle, middle + QPoint(120, 0));
  const ViewCamera after = m_window->sceneView().viewCamera();
  // Trackball: the eye turns about the focal point, keeping its distance.
  EXPECT_GT(glm::length(after.eye - before.eye), 1.0);
  EXPECT_NEAR(glm::length(after.focalPoint - before.focalPoint), 0.0, 1e-9);
  EXPECT_NEAR(glm::length(after.eye - after.focalPoint),
              glm::length(before.eye - before.focalPoint), 1e-6);
}

TEST_F(MainWindowTest, 04_WheelZoomsIn) {
  const ViewCamera before = m_window->sceneView().viewCamera();
  QWidget* w = m_window->viewWidget();
  const QPoint middle = w->rect().center();
  QWheelEvent wheel(middle, w->mapToGlobal(middle), QPoint(), QPoint(0, 120), Qt::NoButton,
                    Qt::NoModifier, Qt::NoScrollPhase, false);
  QApplication::sendEvent(w, &wheel);
  settle();
  const ViewCamera after = m_window->sceneView().viewCamera();
  EXPECT_LT(glm::length(after.eye - after.focalPoint),
            0.95 * glm::length(before.eye - before.focalPoint));
}

// Tracing through the panel records the same tree as the stepper run by hand, draws it
// (the view shows energy-scale rays it did not show before) and shows it whole.
TEST_F(MainWindowTest, 05_TracingAPixelShowsItsTree) {
  const QImage before = grabView();
  EXPECT_FALSE(m_window->sceneView().hasRayTree());
  RayTreePanel& panel = traceCube();

  const Scene scene = defaultScene();
  RenderSettings settings = scene.render;
  settings.algorithm = Algorithm::Whitted;
  const Tracer tracer(scene, settings);
  Stepper stepper(tracer, *panel.viewState().pixelX, *panel.viewState().pixelY, 0);
  stepper.runToEnd();
  ASSERT_TRUE(m_window->sceneView().hasRayTree());
  EXPECT_EQ(m_window->sceneView().rayTree().segments.size(), stepper.tree().segments.size());
  EXPECT_EQ(panel.tree().segments.size(), stepper.tree().segments.size());
  EXPECT_GE(panel.tree().segments.size(), 2u);  // the camera ray and a shadow ray at least
  EXPECT_EQ(panel.frame(), panel.frameCount() - 1);
  EXPECT_TRUE(panel.statusText().contains(QStringLiteral("whole tree")))
      << panel.statusText().toStdString();

  restyle(panel, [](RayTreeStyle& s) { s.showLegend = false; });  // count the rays alone
  const QImage after = grabView();
  EXPECT_LT(rayPixels(before), 5);
  EXPECT_GT(rayPixels(after), 40) << "no energy-coloured rays in the view";
}

// Play starts the timer, whose ticks move the frame on; the picture follows the frame.
TEST_F(MainWindowTest, 06_PlayAdvancesFramesWithTheTimer) {
  RayTreePanel& panel = traceCube();
  panel.setFrame(0);
  EXPECT_EQ(panel.frame(), 0);
  const QImage empty = grabView();
  EXPECT_TRUE(panel.statusText().startsWith(QStringLiteral("Frame 0")));
  // The window says what to press (a video's frame 0, raylab animate, does not).
  EXPECT_TRUE(panel.statusText().endsWith(QStringLiteral("Press Play or Step.")))
      << panel.statusText().toStdString();

  // One tick by hand moves on by the speed (frames per tick).
  panel.setSpeed(3.0);
  panel.play();
  EXPECT_TRUE(panel.playing());
  EXPECT_FALSE(panel.controlForTest<QPushButton>("play")->isEnabled());
  panel.tick();
  EXPECT_EQ(panel.frame(), 3);

  // The timer itself moves it on too (waiting at most 5 s for its ticks).
  QElapsedTimer clock;
  clock.start();
  while (panel.frame() <= 3 && clock.elapsed() < 5000) QApplication::processEvents();
  EXPECT_GT(panel.frame(), 3);
  panel.pause();
  EXPECT_FALSE(panel.playing());

  // Played to the end, it stops there, the whole tree shown.
  while (panel.frame() < panel.frameCount() - 1) panel.tick();
  EXPECT_FALSE(panel.playing());
  EXPECT_EQ(panel.controlForTest<QSlider>("frameSlider")->value(), panel.frameCount() - 1);
  EXPECT_GT(rayPixels(grabView()), rayPixels(empty));
}

// Step forward / back walk whole steps; back returns exactly to the previous picture.
TEST_F(MainWindowTest, 07_StepBackReturnsToThePreviousFrame) {
  RayTreePanel& panel = traceCube();
  restyle(panel, [](RayTreeStyle& s) { s.showLegend = false; });  // see 08
  const int perStep = panel.animation().framesPerStep;
  panel.setFrame(0);
  panel.controlForTest<QPushButton>("stepForward")->click();
  EXPECT_EQ(panel.frame(), perStep);
  EXPECT_EQ(panel.stepAt(panel.frame()), 0);
  const QImage one = grabView();
  const QString oneStatus = panel.statusText();
  EXPECT_TRUE(oneStatus.startsWith(QStringLiteral("Depth 0 of "))) << oneStatus.toStdString();
  EXPECT_TRUE(oneStatus.contains(QStringLiteral("1 camera"))) << oneStatus.toStdString();

  panel.controlForTest<QPushButton>("stepForward")->click();
  EXPECT_EQ(panel.frame(), 2 * perStep);
  const QImage two = grabView();
  EXPECT_NE(one, two);  // depth 1 arrived

  panel.controlForTest<QPushButton>("stepBack")->click();
  EXPECT_EQ(panel.frame(), perStep);
  EXPECT_EQ(grabView(), one);
  EXPECT_EQ(panel.statusText(), oneStatus);

  // Mid-step, back goes to the start of that step's travel; never below frame 0.
  panel.setFrame(perStep + 5);
  panel.stepBack();
  EXPECT_EQ(panel.frame(), perStep);
  panel.stepBack();
  panel.stepBack();
  EXPECT_EQ(panel.frame(), 0);

  // In processing order, the status line tells what that ray did (the stepper's words).
  panel.setAnimation({RevealOrder::Processing, perStep, 1});
  panel.setFrame(perStep);
  EXPECT_TRUE(panel.statusText().contains(QStringLiteral("camera ray #0 hit 'blue cube'")))
      << panel.statusText().toStdString();
}

// Unticking a kind hides those rays (the style reaches the view and the picture changes);
// ticking it again gives the same picture back.
TEST_F(MainWindowTest, 08_KindFilterChangesWhatIsDrawn) {
  RayTreePanel& panel = traceCube();
  // Exact picture comparisons without the legend: VTK may place its labels a pixel
  // differently from one redraw to the next.
  restyle(panel, [](RayTreeStyle& s) { s.showLegend = false; });
  const QImage all = grabView();
  EXPECT_EQ(panel.hiddenRays(), 0);
  EXPECT_FALSE(panel.traceInfoText().contains(QStringLiteral("filters hide")));
  panel.controlForTest<QCheckBox>("kind-shadow")->click();
  EXPECT_FALSE(m_window->sceneView().rayTreeStyle().filter.kinds[std::size_t(RayKind::Shadow)]);
  const QImage noShadows = grabView();
  EXPECT_NE(all, noShadows);
  // The summary under Trace counts every ray; a line says how many the filters hide.
  int shadows = 0;
  for (const RaySegment& s : panel.tree().segments) shadows += s.kind == RayKind::Shadow;
  ASSERT_GT(shadows, 0);
  EXPECT_EQ(panel.hiddenRays(), shadows);
  EXPECT_TRUE(panel.traceInfoText().endsWith(
      QStringLiteral("The filters hide %1 of these rays.").arg(shadows)))
      << panel.traceInfoText().toStdString();
  panel.controlForTest<QCheckBox>("kind-shadow")->click();
  EXPECT_TRUE(m_window->sceneView().rayTreeStyle().filter.kinds[std::size_t(RayKind::Shadow)]);
  EXPECT_EQ(grabView(), all);
  EXPECT_EQ(panel.hiddenRays(), 0);
  EXPECT_FALSE(panel.traceInfoText().contains(QStringLiteral("filters hide")));

  // The other controls reach the style too.
  restyle(panel, [](RayTreeStyle& s) {
    s.filter.maxDepth = 0;
    s.filter.onlyReachingLight = true;
    s.showNormals = true;
  });
  const RayTreeStyle style = m_window->sceneView().rayTreeStyle();
  EXPECT_EQ(style.filter.maxDepth, 0);
  EXPECT_TRUE(style.filter.onlyReachingLight);
  EXPECT_TRUE(style.showNormals);
}

// A click on a ray selects it in the view and fills the inspector with its values; a
// click on empty space clears the selection; a drag selects nothing.
TEST_F(MainWindowTest, 09_ClickingARayInspectsIt) {
  RayTreePanel& panel = traceCube();
  InspectorPanel& inspector = *m_window->inspectorPanel();
  EXPECT_EQ(inspector.segment(), -1);

  // The middle of the camera ray, where the view draws it.
  QWidget* w = m_window->viewWidget();
  const RaySegment& camera = panel.tree().segments[0];
  const std::optional<Vec2> middle = m_window->sceneView().worldToImage(
      0.5 * (camera.origin + camera.endPoint), w->width(), w->height());
  ASSERT_TRUE(middle.has_value());
  const QPoint at(int(std::lround(middle->x)), int(std::lround(middle->y)));
  click(at);
  EXPECT_EQ(panel.selectedSegment(), 0);
  EXPECT_EQ(m_window->sceneView().selectedSegment(), 0);
  EXPECT_EQ(inspector.segment(), 0);
  EXPECT_EQ(inspector.segmentBox()->value(), 0);
  // What a student asks comes first; the exact oracle's figures are one click away.
  const std::string words = inspector.text().toStdString();
  EXPECT_EQ(words.rfind("camera ray, depth 0\nWhere: it hit 'blue cube', ", 0), 0u) << words;
  EXPECT_NE(words.find("What it carried: 100.0% of the light this pixel sample found"),
            std::string::npos)
      << words;
  EXPECT_NE(words.find("Why it stopped: "), std::string::npos) << words;
  EXPECT_EQ(words.find("Exact oracle (CGAL)"), std::string::npos) << words;
  inspector.exactButton()->click();
  const std::string text = inspector.text().toStdString();
  const RayInspection expected = RayInspector::inspect(defaultScene(), panel.tree(), 0);
  EXPECT_NE(text.find("Ray #0: camera ray, depth 0"), std::string::npos) << text;
  EXPECT_NE(text.find("object      'blue cube'\n  material    'blue' (glossy)"), std::string::npos)
      << text;
  EXPECT_NE(text.find(rayText(expected, Language::English).substr(0, 200)), std::string::npos)
      << text;
  EXPECT_NE(text.find("Exact oracle (CGAL) on 'blue cube'"), std::string::npos);
  EXPECT_NE(text.find("agrees with double precision"), std::string::npos) << text;

  // Walk to its first child and back to the parent with the inspector's buttons.
  inspector.childButton()->click();
  EXPECT_EQ(panel.selectedSegment(), camera.firstChild);
  EXPECT_EQ(inspector.segment(), camera.firstChild);
  inspector.parentButton()->click();
  EXPECT_EQ(inspector.segment(), 0);

  // A drag from the ray selects nothing new; a click in an empty corner clears.
  drag(at, at + QPoint(1, 40));
  EXPECT_EQ(panel.selectedSegment(), 0);
  click(QPoint(3, 3));
  EXPECT_EQ(panel.selectedSegment(), -1);
  EXPECT_EQ(m_window->sceneView().selectedSegment(), -1);
  EXPECT_EQ(inspector.segment(), -1);
}

/// The file's bytes ("" when it cannot be read).
QByteArray fileBytes(const QString& path) {
  QFile file(path);
  return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

// File > Open of a good file shows it (title, list, view); a bad file shows the loader's
// whole message in a dialog and the scene that was open stays open, unchanged.
TEST_F(MainWindowTest, 10_OpenAGoodFileAndABadOne) {
  const QString dir = scratch(QStringLiteral("open"));
  const QString good = QString::fromLatin1(RAYLAB_SOURCE_DIR) + "/lessons/scenes/cornell.json";
  ASSERT_TRUE(m_window->openFile(good));
  const Scene cornell = SceneIO::load(good.toStdString());
  EXPECT_EQ(SceneIO::serialize(m_window->document().scene()), SceneIO::serialize(cornell));
  EXPECT_EQ(m_window->objectList()->count(), int(cornell.objects.size()));
  EXPECT_TRUE(m_window->windowTitle().startsWith(QStringLiteral("cornell.json")));
  EXPECT_FALSE(m_window->isWindowModified());
  EXPECT_EQ(m_window->recentFiles().front(), QFileInfo(good).absoluteFilePath());

  const QString bad = dir + "/bad.json";
  QFile file(bad);
  ASSERT_TRUE(file.open(QIODevice::WriteOnly));
  file.write(
      R"({"raylab_scene": 2, "materials": [{"name": "red", "colour": [1, 0, 0]}],
          "objects": [{"name": "ball", "material": "red",
                       "shape": {"type": "sphere", "centre": [0, 0, 0], "radius": -1}}]})");
  file.close();
  const std::string before = SceneIO::serialize(m_window->document().scene());
  EXPECT_FALSE(m_window->openFile(bad));
  EXPECT_TRUE(m_window->lastError().contains(bad)) << m_window->lastError().toStdString();
  EXPECT_TRUE(m_window->lastError().contains(
      QStringLiteral("at /objects/0/shape/radius: radius must be positive")))
      << m_window->lastError().toStdString();
  EXPECT_EQ(SceneIO::serialize(m_window->document().scene()), before);
  EXPECT_EQ(m_window->document().path(), good);
}

// Save writes the scene atomically and it reads back equal; a save that fails (the disk
// full: a file size limit) shows a dialog and leaves the old file intact.
TEST_F(MainWindowTest, 11_SaveAndReloadAndAFailedSaveKeepsTheOldFile) {
  const QString dir = scratch(QStringLiteral("save"));
  const QString path = dir + "/classroom.json";
  ASSERT_TRUE(m_window->saveFile(path));
  EXPECT_EQ(SceneIO::serialize(SceneIO::load(path.toStdString())),
            SceneIO::serialize(m_window->document().scene()));
  EXPECT_FALSE(m_window->isWindowModified());

  // Make the scene larger, then save with a file size limit below its size.
  m_window->selectObject(m_window->document().scene().findObject("red sphere"));
  for (int i = 0; i < 4; ++i) m_window->editPanel()->duplicate();
  EXPECT_TRUE(m_window->isWindowModified());
  const QByteArray old = fileBytes(path);
  rlimit previous{};
  getrlimit(RLIMIT_FSIZE, &previous);
  signal(SIGXFSZ, SIG_IGN);
  rlimit limit = previous;
  limit.rlim_cur = rlim_t(old.size() + 16);
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &limit), 0);
  const bool saved = m_window->saveFile(path);
  setrlimit(RLIMIT_FSIZE, &previous);
  EXPECT_FALSE(saved);
  EXPECT_TRUE(m_window->lastError().contains(path)) << m_window->lastError().toStdString();
  EXPECT_EQ(fileBytes(path), old);
  EXPECT_TRUE(m_window->isWindowModified());
  EXPECT_EQ(QDir(dir).entryList(QDir::Files), QStringList{QStringLiteral("classroom.json")});

  // A place nobody can write to (root included): a dialog naming the file.
  EXPECT_FALSE(m_window->saveFile(QStringLiteral("/proc/raylab-classroom.json")));
  EXPECT_TRUE(m_window->lastError().contains(QStringLiteral("/proc/raylab-classroom.json")));
  EXPECT_EQ(m_window->document().path(), path);
}

// The original program's operation: the blue cube turned 90 degrees about z through its
// centre, as one undo step with a readable name; undo gives the scene back.
TEST_F(MainWindowTest, 12_RotateTheCubeAndUndo) {
  const Scene& scene = m_window->document().scene();
  const int cube = scene.findObject("blue cube");
  const auto before = static_cast<const Box&>(*scene.objects[std::size_t(cube)].shape).vertices();
  const Point3 c = scene.objects[std::size_t(cube)].shape->bounds().centre();
  const std::string original = SceneIO::serialize(scene);
  m_window->selectObject(cube);
  EditPanel& edit = *m_window->editPanel();
  edit.angleBox()->setValue(90.0);
  EXPECT_EQ(edit.axisBox(2)->value(), 1.0);  // the original's default axis (0, 0, 1)
  edit.rotateButton()->click();
  settle();
  const auto after =
      static_cast<const Box&>(*m_window->document().scene().objects[std::size_t(cube)].shape)
          .vertices();
  for (int k = 0; k < 8; ++k) {
    const Vec3 d = before[std::size_t(k)] - c;
    EXPECT_NEAR(glm::length(after[std::size_t(k)] - (c + Vec3(-d.y, d.x, d.z))), 0.0, 1e-9);
  }
  EXPECT_EQ(m_window->document().undoStack().undoText(),
            QStringLiteral("Rotate blue cube 90° about z"));
  EXPECT_TRUE(m_window->isWindowModified());
  EXPECT_EQ(m_window->selectedObject(), cube);  // still selected
  m_window->document().undoStack().undo();
  EXPECT_EQ(SceneIO::serialize(m_window->document().scene()), original);
  EXPECT_FALSE(m_window->isWindowModified());
}

// Delete (the Del key), duplicate and add, each one step; the list follows.
TEST_F(MainWindowTest, 13_DeleteDuplicateAndAdd) {
  const int count = int(m_window->document().scene().objects.size());
  m_window->selectObject(m_window->document().scene().findObject("red sphere"));
  activate();
  QTest::keyClick(m_window->viewWidget(), Qt::Key_Delete);
  settle();
  EXPECT_EQ(int(m_window->document().scene().objects.size()), count - 1);
  EXPECT_LT(m_window->document().scene().findObject("red sphere"), 0);
  EXPECT_EQ(m_window->objectList()->count(), count - 1);
  EXPECT_EQ(m_window->selectedObject(), -1);

  m_window->selectObject(m_window->document().scene().findObject("blue cube"));
  m_window->editPanel()->duplicate();
  EXPECT_EQ(int(m_window->document().scene().objects.size()), count);
  EXPECT_EQ(m_window->document().scene().objects.back().name, "blue cube copy");
  EXPECT_EQ(m_window->selectedObject(), count - 1);  // the copy is selected

  for (QAction* action : m_window->addMenu()->actions())
    if (action->text() == QStringLiteral("Sphere")) action->trigger();
  settle();
  EXPECT_EQ(int(m_window->document().scene().objects.size()), count + 1);
  EXPECT_EQ(m_window->document().scene().objects.back().name, "sphere");
  EXPECT_EQ(m_window->selectedObject(), count);
  EXPECT_EQ(m_window->document().undoStack().count(), 3);
}

// A material's parameter edited in the properties panel, then undone: the scene saves
// byte for byte as before. An invalid value is refused with the loader's message in a
// dialog, and nothing changes.
TEST_F(MainWindowTest, 14_EditAMaterialUndoItAndARefusedValue) {
  const std::string original = SceneIO::serialize(m_window->document().scene());
  const int sphere = m_window->document().scene().findObject("red sphere");
  m_window->selectObject(sphere);
  PropertiesPanel& properties = *m_window->propertiesPanel();
  const int material = m_window->document().scene().objects[std::size_t(sphere)].material;
  const std::string colour = "/materials/" + std::to_string(material) + "/colour";
  ASSERT_NE(properties.field(colour), nullptr);
  // Through the field's first spin box, as a teacher types a value.
  auto* red = properties.field(colour)->findChild<QDoubleSpinBox*>();
  ASSERT_NE(red, nullptr);
  red->setValue(0.25);
  settle();
  EXPECT_NEAR(m_window->document().scene().materials[std::size_t(material)].colour.x, 0.25, 1e-12);
  EXPECT_NE(SceneIO::serialize(m_window->document().scene()), original);
  m_window->document().undoStack().undo();
  EXPECT_EQ(SceneIO::serialize(m_window->document().scene()), original);

  const std::string radius = "/objects/" + std::to_string(sphere) + "/shape/radius";
  ASSERT_NE(properties.field(radius), nullptr);
  EXPECT_FALSE(properties.setValue(radius, "0", QStringLiteral("radius")));
  EXPECT_TRUE(m_window->lastError().contains(QStringLiteral("radius must be positive")))
      << m_window->lastError().toStdString();
  EXPECT_EQ(SceneIO::serialize(m_window->document().scene()), original);
  EXPECT_FALSE(m_window->document().undoStack().canUndo());
  // A zero rotation axis is refused the same way.
  m_window->editPanel()->axisBox(2)->setValue(0.0);
  m_window->editPanel()->rotate();
  EXPECT_TRUE(
      m_window->lastError().contains(QStringLiteral("rotate/axis: vector must not be zero")));
  EXPECT_EQ(SceneIO::serialize(m_window->document().scene()), original);
}

// An object the file turns and moves with transform steps: the panel shows the shape's
// values (before the steps) and the steps themselves, each editable; a turn in the Edit tab
// adds steps, which the panel then lists too.
TEST_F(MainWindowTest, 14a_TransformStepsAreShownAndEdited) {
  const Scene turned = SceneIO::parse(R"({"raylab_scene": 2,
    "materials": [{"name": "m"}, {"name": "lamp", "emission": [5, 5, 5]}],
    "objects": [{"name": "cube", "material": "m",
      "shape": {"type": "box", "centre": [0, 0, 0], "size": [1, 1, 1]},
      "transform": [{"rotate": {"axis": [0, 1, 0], "degrees": 35}}, {"translate": [0.3, 0.6, 0.6]}]},
      {"name": "light", "material": "lamp",
       "shape": {"type": "quad", "corner": [-1, 3, -1], "u": [2, 0, 0], "v": [0, 0, 2]}}]})",
                                      "turned.json");
  m_window->document().adopt(turned, {});
  settle();
  m_window->selectObject(0);
  PropertiesPanel& properties = *m_window->propertiesPanel();
  ASSERT_NE(properties.field("/objects/0/shape/size"), nullptr);
  QWidget* degrees = properties.field("/objects/0/transform/0/rotate/degrees");
  ASSERT_NE(degrees, nullptr);
  ASSERT_NE(properties.field("/objects/0/transform/0/rotate/axis"), nullptr);
  ASSERT_NE(properties.field("/objects/0/transform/1/translate"), nullptr);
  // 35 degrees typed as 90: the cube turns a quarter, still moved by the second step.
  auto* angle = qobject_cast<QDoubleSpinBox*>(degrees);
  if (!angle) angle = degrees->findChild<QDoubleSpinBox*>();
  ASSERT_NE(angle, nullptr);
  angle->setValue(90.0);
  settle();
  const auto& box = static_cast<const Box&>(*m_window->document().scene().objects[0].shape);
  EXPECT_NEAR(glm::length(box.centre() - Point3(0.3, 0.6, 0.6)), 0.0, 1e-12);
  EXPECT_NEAR(std::abs(box.axis(0).z), 1.0, 1e-12);  // x turned onto -z
  // A turn in the Edit tab adds three steps (to its centre, the turn, back).
  m_window->editPanel()->rotate();
  settle();
  EXPECT_NE(properties.field("/objects/0/transform/3/rotate/degrees"), nullptr);
}

// The materials added to the scene format are offered in the properties panel: the
// sphere's material switched to rough_conductor shows that model's fields, its roughness
// set through the spin box reaches the scene, a roughness the loader refuses is refused
// with its message, and undo brings the scene back byte for byte. The render block shows
// the ray offset, which the file leaves out while it is on.
TEST_F(MainWindowTest, 14b_SwitchToARoughConductorAndSetItsRoughness) {
  const std::string original = SceneIO::serialize(m_window->document().scene());
  const int sphere = m_window->document().scene().findObject("red sphere");
  m_window->selectObject(sphere);
  PropertiesPanel& properties = *m_window->propertiesPanel();
  const std::size_t material =
      std::size_t(m_window->document().scene().objects[std::size_t(sphere)].material);
  const std::string base = "/materials/" + std::to_string(material);
  ASSERT_NE(m_window->document().scene().materials[material].type, MaterialType::RoughConductor);
  auto* type = qobject_cast<QComboBox*>(properties.field(base + "/type"));
  ASSERT_NE(type, nullptr);
  for (const char* offered : {"phong", "blinn_phong", "rough_conductor", "rough_dielectric"})
    EXPECT_GE(type->findData(QString::fromLatin1(offered)), 0) << offered;
  type->setCurrentIndex(type->findData(QStringLiteral("rough_conductor")));
  emit type->activated(type->currentIndex());
  settle();
  EXPECT_EQ(m_window->document().scene().materials[material].type, MaterialType::RoughConductor);

  // The form now shows the microfacet model's parameters.
  auto* distribution = qobject_cast<QComboBox*>(properties.field(base + "/distribution"));
  ASSERT_NE(distribution, nullptr);
  EXPECT_EQ(distribution->currentData().toString(), QStringLiteral("ggx"));
  EXPECT_GE(distribution->findData(QStringLiteral("beckmann")), 0);
  EXPECT_NE(qobject_cast<QCheckBox*>(properties.field(base + "/visible_normals")), nullptr);
  auto* roughness = qobject_cast<QDoubleSpinBox*>(properties.field(base + "/roughness"));
  ASSERT_NE(roughness, nullptr);
  EXPECT_FALSE(roughness->toolTip().isEmpty());
  roughness->setValue(0.05);
  settle();
  EXPECT_NEAR(m_window->document().scene().materials[material].roughness, 0.05, 1e-12);
  const std::string rough = SceneIO::serialize(m_window->document().scene());

  roughness = qobject_cast<QDoubleSpinBox*>(properties.field(base + "/roughness"));
  ASSERT_NE(roughness, nullptr);
  roughness->setValue(0.0);
  settle();
  EXPECT_TRUE(m_window->lastError().contains(
      QStringLiteral("roughness (alpha) must be in [0.0001, 4], got 0")))
      << m_window->lastError().toStdString();
  EXPECT_EQ(SceneIO::serialize(m_window->document().scene()), rough);

  m_window->document().undoStack().undo();  // the roughness
  EXPECT_NEAR(m_window->document().scene().materials[material].roughness, Material{}.roughness,
              1e-12);
  m_window->document().undoStack().undo();  // the type
  EXPECT_EQ(SceneIO::serialize(m_window->document().scene()), original);
  EXPECT_FALSE(m_window->document().undoStack().canUndo());

  properties.showObject(-1);
  auto* offset = qobject_cast<QCheckBox*>(properties.field("/render/ray_offset"));
  ASSERT_NE(offset, nullptr);
  EXPECT_TRUE(offset->isChecked());
  offset->setChecked(false);
  settle();
  EXPECT_FALSE(m_window->document().scene().render.rayOffset);
  m_window->document().undoStack().undo();
  EXPECT_TRUE(m_window->document().scene().render.rayOffset);
}

// Issue 37 in the properties panel: the red mirror sphere's "fresnel" shown as none although
// the file leaves it out, set to schlick it reaches the scene; the type plastic is offered
// and shows its coating's roughness; a dielectric shows its nesting priority (0), set to 2
// it reaches the scene; undo brings the scene back byte for byte.
TEST_F(MainWindowTest, 14b2_FresnelRatesPlasticAndPriority) {
  const std::string original = SceneIO::serialize(m_window->document().scene());
  const int sphere = m_window->document().scene().findObject("red sphere");
  m_window->selectObject(sphere);
  PropertiesPanel& properties = *m_window->propertiesPanel();
  const std::size_t material =
      std::size_t(m_window->document().scene().objects[std::size_t(sphere)].material);
  const std::string base = "/materials/" + std::to_string(material);
  ASSERT_EQ(m_window->document().scene().materials[material].type, MaterialType::Mirror);
  auto* fresnel = qobject_cast<QComboBox*>(properties.field(base + "/fresnel"));
  ASSERT_NE(fresnel, nullptr);
  EXPECT_EQ(fresnel->currentData().toString(), QStringLiteral("none"));
  EXPECT_FALSE(fresnel->toolTip().isEmpty());
  fresnel->setCurrentIndex(fresnel->findData(QStringLiteral("schlick")));
  emit fresnel->activated(fresnel->currentIndex());
  settle();
  EXPECT_EQ(m_window->document().scene().materials[material].rateFresnel, FresnelModel::Schlick);

  auto* type = qobject_cast<QComboBox*>(properties.field(base + "/type"));
  ASSERT_NE(type, nullptr);
  type->setCurrentIndex(type->findData(QStringLiteral("plastic")));
  emit type->activated(type->currentIndex());
  settle();
  EXPECT_EQ(m_window->document().scene().materials[material].type, MaterialType::Plastic);
  EXPECT_NE(qobject_cast<QDoubleSpinBox*>(properties.field(base + "/roughness")), nullptr);

  type = qobject_cast<QComboBox*>(properties.field(base + "/type"));
  ASSERT_NE(type, nullptr);
  type->setCurrentIndex(type->findData(QStringLiteral("dielectric")));
  emit type->activated(type->currentIndex());
  settle();
  auto* priority = qobject_cast<QSpinBox*>(properties.field(base + "/priority"));
  ASSERT_NE(priority, nullptr);
  EXPECT_EQ(priority->value(), 0);
  priority->setValue(2);
  settle();
  EXPECT_EQ(m_window->document().scene().materials[material].priority, 2);

  for (int i = 0; i < 4; ++i) m_window->document().undoStack().undo();
  EXPECT_EQ(SceneIO::serialize(m_window->document().scene()), original);
}

// The checker texture (issue 32): the material's box switches it on (a checker of the
// default side 1 and a dark second colour), its scale is typed, a zero scale is refused with
// the loader's message, the box switches it off again, and undo walks back to the file.
TEST_F(MainWindowTest, 14b3_CheckerTextureOnOffAndARefusedScale) {
  const std::string original = SceneIO::serialize(m_window->document().scene());
  const int sphere = m_window->document().scene().findObject("red sphere");
  m_window->selectObject(sphere);
  PropertiesPanel& properties = *m_window->propertiesPanel();
  const std::size_t material =
      std::size_t(m_window->document().scene().objects[std::size_t(sphere)].material);
  const std::string base = "/materials/" + std::to_string(material);
  const auto textureOf = [&] { return m_window->document().scene().materials[material].texture; };
  auto* box = qobject_cast<QCheckBox*>(properties.field(base + "/texture"));
  ASSERT_NE(box, nullptr);
  EXPECT_FALSE(box->isChecked());
  EXPECT_FALSE(box->toolTip().isEmpty());
  EXPECT_EQ(properties.field(base + "/texture/scale"), nullptr);
  box->setChecked(true);
  settle();
  EXPECT_EQ(textureOf().type, TextureType::Checker);
  EXPECT_EQ(textureOf().scale, 1.0);

  auto* scale = qobject_cast<QDoubleSpinBox*>(properties.field(base + "/texture/scale"));
  ASSERT_NE(scale, nullptr);
  scale->setValue(0.25);
  settle();
  EXPECT_EQ(textureOf().scale, 0.25);
  ASSERT_NE(properties.field(base + "/texture/colour2"), nullptr);
  EXPECT_NE(properties.field(base + "/texture/colour2")->findChild<QPushButton*>(), nullptr);
  EXPECT_FALSE(properties.setValue(base + "/texture/scale", "0", QStringLiteral("scale")));
  EXPECT_TRUE(m_window->lastError().contains(
      QString::fromStdString(base + "/texture/scale: scale (a checker cube's side) must be "
                                    "positive, got 0")))
      << m_window->lastError().toStdString();
  EXPECT_EQ(textureOf().scale, 0.25);

  box = qobject_cast<QCheckBox*>(properties.field(base + "/texture"));
  ASSERT_NE(box, nullptr);
  EXPECT_TRUE(box->isChecked());
  box->setChecked(false);
  settle();
  EXPECT_FALSE(textureOf().active());
  EXPECT_EQ(SceneIO::serialize(m_window->document().scene()), original);
  for (int i = 0; i < 3; ++i) m_window->document().undoStack().undo();
  EXPECT_EQ(SceneIO::serialize(m_window->document().scene()), original);
  EXPECT_FALSE(m_window->document().undoStack().canUndo());
}

// A mesh's shading normals are offered in the properties panel: "file" shown although the
// file leaves it out, switched to "smooth" the crease angle appears (60), set to 30 it
// reaches the scene, 200 is refused with the loader's message, and undo restores the file.
TEST_F(MainWindowTest, 14c_SmoothAMeshAndSetItsCreaseAngle) {
  m_window->document().open(QString::fromLatin1(RAYLAB_SOURCE_DIR) +
                            "/lessons/scenes/smooth-shading.json");
  settle();
  const Scene& scene = m_window->document().scene();
  const int ball = scene.findObject("smooth (file normals)");
  ASSERT_GE(ball, 0);
  const std::string original = SceneIO::serialize(scene);
  m_window->selectObject(ball);
  PropertiesPanel& properties = *m_window->propertiesPanel();
  const std::string base = "/objects/" + std::to_string(ball) + "/shape";
  auto* normals = qobject_cast<QComboBox*>(properties.field(base + "/normals"));
  ASSERT_NE(normals, nullptr);
  EXPECT_EQ(normals->currentData().toString(), QStringLiteral("file"));
  EXPECT_GE(normals->findData(QStringLiteral("flat")), 0);
  EXPECT_FALSE(normals->toolTip().isEmpty());
  EXPECT_EQ(properties.field(base + "/crease_angle"), nullptr);
  normals->setCurrentIndex(normals->findData(QStringLiteral("smooth")));
  emit normals->activated(normals->currentIndex());
  settle();
  EXPECT_EQ(m_window->document().scene().objects[std::size_t(ball)].meshNormals,
            MeshNormals::Smooth);

  auto* crease = qobject_cast<QDoubleSpinBox*>(properties.field(base + "/crease_angle"));
  ASSERT_NE(crease, nullptr);
  EXPECT_EQ(crease->value(), 60.0);
  crease->setValue(30.0);
  settle();
  EXPECT_EQ(m_window->document().scene().objects[std::size_t(ball)].creaseAngle, 30.0);
  crease = qobject_cast<QDoubleSpinBox*>(properties.field(base + "/crease_angle"));
  ASSERT_NE(crease, nullptr);
  crease->setValue(200.0);
  settle();
  EXPECT_TRUE(m_window->lastError().contains(
      QStringLiteral("/shape/crease_angle: crease angle 200.0 must be in [0, 180] degrees")))
      << m_window->lastError().toStdString();
  m_window->document().undoStack().undo();  // the crease angle
  m_window->document().undoStack().undo();  // smooth
  EXPECT_EQ(SceneIO::serialize(m_window->document().scene()), original);
  EXPECT_FALSE(m_window->document().undoStack().canUndo());
}

// Simulate 2 x 2: four camera rays spread over the image, each tree equal to
// tracePixel of its pixel (what `raylab trace --pixel` draws), shown together.
TEST_F(MainWindowTest, 15_Simulate2x2DrawsFourTrees) {
  RayTreePanel& panel = *m_window->rayTreePanel();
  panel.setAlgorithm(Algorithm::PathTracing);
  panel.setGrid(2, 2);
  panel.controlForTest<QPushButton>("simulate")->click();
  settle();
  ASSERT_TRUE(panel.showsGrid());
  const Scene& scene = m_window->document().scene();
  RenderSettings settings = scene.render;
  settings.algorithm = Algorithm::PathTracing;
  const RayTree& shown = m_window->sceneView().rayTree();
  std::size_t offset = 0, cameras = 0;
  for (const auto& [x, y] : gridPixels(scene.camera.width, scene.camera.height, 2, 2)) {
    const PixelTrace single = tracePixel(scene, settings, x, y, 0);
    ASSERT_LE(offset + single.tree.segments.size(), shown.segments.size());
    for (std::size_t i = 0; i < single.tree.segments.size(); ++i) {
      const RaySegment& a = single.tree.segments[i];
      const RaySegment& b = shown.segments[offset + i];
      EXPECT_EQ(a.origin, b.origin);
      EXPECT_EQ(a.endPoint, b.endPoint);
      EXPECT_EQ(a.radiance, b.radiance);
      EXPECT_EQ(a.kind, b.kind);
    }
    offset += single.tree.segments.size();
    ++cameras;
  }
  EXPECT_EQ(offset, shown.segments.size());
  EXPECT_EQ(cameras, 4u);
  int roots = 0;
  for (const RaySegment& s : shown.segments) roots += s.kind == RayKind::Camera;
  EXPECT_EQ(roots, 4);
  EXPECT_EQ(gridPixels(320, 240, 1, 1).front(), std::make_pair(160, 120));  // 1 x 1: the centre
}

// Simulate colours the grid by energy. From another colouring, with a pixel's tree shown or
// none, the view must take the new tree before its colours change: the window aborted
// (a reveal of the grid's rays checked against the tree still drawn).
TEST_F(MainWindowTest, 15b_SimulateFromAnotherColouring) {
  RayTreePanel& panel = *m_window->rayTreePanel();
  panel.setAlgorithm(Algorithm::Whitted);
  restyle(panel, [](RayTreeStyle& s) { s.colouring = RayColouring::Kind; });
  panel.setGrid(2, 2);
  panel.controlForTest<QPushButton>("simulate")->click();
  settle();
  ASSERT_TRUE(panel.showsGrid());
  EXPECT_EQ(panel.treeStyle().colouring, RayColouring::Energy);
  EXPECT_EQ(m_window->sceneView().rayTreeStyle().colouring, RayColouring::Energy);
  int roots = 0;
  for (const RaySegment& s : m_window->sceneView().rayTree().segments)
    roots += s.kind == RayKind::Camera;
  EXPECT_EQ(roots, 4);
  // Again from "depth", over the grid now shown.
  restyle(panel, [](RayTreeStyle& s) { s.colouring = RayColouring::Depth; });
  panel.setGrid(3, 2);
  panel.controlForTest<QPushButton>("simulate")->click();
  settle();
  roots = 0;
  for (const RaySegment& s : m_window->sceneView().rayTree().segments)
    roots += s.kind == RayKind::Camera;
  EXPECT_EQ(roots, 6);
}

// Start-up opens the scene open last time; when it cannot be read, the default scene,
// and the status bar says why.
TEST_F(MainWindowTest, 16_StartUpWithTheLastSceneOrTheDefault) {
  const QString good = QString::fromLatin1(RAYLAB_SOURCE_DIR) + "/lessons/scenes/materials.json";
  QSettings(QSettings::IniFormat, QSettings::UserScope, "RayLab", "RayLab")
      .setValue("lastScene", good);
  MainWindow first(defaultScene());
  first.startUp();
  EXPECT_EQ(first.document().path(), good);
  EXPECT_TRUE(first.statusBar()->currentMessage().contains(QStringLiteral("open last time")));

  const QString gone = scratch(QStringLiteral("startup")) + "/gone.json";
  QSettings(QSettings::IniFormat, QSettings::UserScope, "RayLab", "RayLab")
      .setValue("lastScene", gone);
  MainWindow second(defaultScene());
  second.startUp();
  EXPECT_TRUE(second.document().path().isEmpty());
  EXPECT_EQ(SceneIO::serialize(second.document().scene()), SceneIO::serialize(defaultScene()));
  const QString message = second.statusBar()->currentMessage();
  EXPECT_TRUE(message.contains(QStringLiteral("could not be read")) && message.contains(gone))
      << message.toStdString();
}

// Clicking an object in the view (without dragging) selects it in the list; Escape clears;
// VTK's own keys (w: wireframe) do nothing.
TEST_F(MainWindowTest, 17_ClickAnObjectEscapeAndNoVtkKeys) {
  const Scene& scene = m_window->document().scene();
  const int sphere = scene.findObject("red sphere");
  QWidget* w = m_window->viewWidget();
  const std::optional<Vec2> at = m_window->sceneView().worldToImage(
      m_window->sceneView().objectCentre(sphere), w->width(), w->height());
  ASSERT_TRUE(at.has_value());
  click(QPoint(int(at->x), int(at->y)));
  EXPECT_EQ(m_window->selectedObject(), sphere);
  EXPECT_EQ(m_window->objectList()->currentRow(), sphere);
  EXPECT_EQ(m_window->sceneView().highlighted(), sphere);
  activate();
  QTest::keyClick(m_window->viewWidget(), Qt::Key_Escape);
  settle();
  EXPECT_EQ(m_window->selectedObject(), -1);
  EXPECT_EQ(m_window->sceneView().highlighted(), -1);

  const QImage before = grabView();
  QTest::keyClick(w, Qt::Key_W);
  QTest::keyClick(w, Qt::Key_S);
  EXPECT_EQ(grabView(), before);
}

// A tree on screen always belongs to the algorithm chosen and to the scene as edited.
TEST_F(MainWindowTest, 18_TreesAreRetracedAfterAnEditOrAnotherAlgorithm) {
  // Whitted through the red (mirror) sphere: reflection and refraction rays.
  RayTreePanel& panel = *m_window->rayTreePanel();
  const Scene& scene = m_window->document().scene();
  const auto [x, y] = pixelOn(scene, "red sphere");
  panel.setAlgorithm(Algorithm::Whitted);
  panel.setPixel(x, y);
  panel.controlForTest<QPushButton>("trace")->click();
  settle();
  EXPECT_GT(panel.tree().segments.size(), 3u);
  // Ray casting chosen: the tree shown is ray casting's, the camera ray alone (the
  // sphere has no local shading under ray casting).
  auto* algorithms = panel.controlForTest<QComboBox>("algorithm");
  algorithms->setCurrentIndex(algorithms->findData(QStringLiteral("raycast")));
  emit algorithms->activated(algorithms->currentIndex());
  settle();
  EXPECT_EQ(panel.algorithm(), Algorithm::RayCasting);
  EXPECT_EQ(panel.tree().segments.size(), 1u);
  EXPECT_EQ(m_window->sceneView().rayTree().segments.size(), 1u);
  // Move the sphere away: the tree is traced again in the edited scene.
  m_window->selectObject(scene.findObject("red sphere"));
  m_window->editPanel()->offsetBox(0)->setValue(-10.0);
  m_window->editPanel()->move();
  settle();
  const Scene& moved = m_window->document().scene();
  RenderSettings settings = moved.render;
  settings.algorithm = Algorithm::RayCasting;
  EXPECT_EQ(panel.tree().segments.size(), tracePixel(moved, settings, x, y).tree.segments.size());
  EXPECT_NE(panel.tree().segments[0].object, moved.findObject("red sphere"));
}

// With unsaved changes the title carries the marker, and New (like Open and closing) asks
// Save / Discard / Cancel: Cancel keeps the edits, Discard drops them.
TEST_F(MainWindowTest, 19_UnsavedChangesAreAskedAbout) {
  m_window->selectObject(m_window->document().scene().findObject("blue cube"));
  m_window->editPanel()->duplicate();
  EXPECT_TRUE(m_window->isWindowModified());
  EXPECT_TRUE(m_window->windowTitle().contains(QStringLiteral("[*]")));
  const std::size_t edited = m_window->document().scene().objects.size();
  m_window->setUnsavedChangesAnswer(QMessageBox::Cancel);
  m_window->newScene();
  EXPECT_EQ(m_window->document().scene().objects.size(), edited);
  EXPECT_TRUE(m_window->isWindowModified());
  m_window->setUnsavedChangesAnswer(QMessageBox::Discard);
  m_window->newScene();
  EXPECT_EQ(SceneIO::serialize(m_window->document().scene()), SceneIO::serialize(defaultScene()));
  EXPECT_FALSE(m_window->isWindowModified());
  EXPECT_FALSE(m_window->document().undoStack().canUndo());
}

TEST_F(MainWindowTest, 20_PresentationModeAndItsKeys) {
  RayTreePanel& panel = traceCube();
  const double font = m_window->rayTreePanel()->font().pointSizeF();
  const QString textBefore = m_window->rayTreePanel()->font().toString();
  activate();
  QTest::keyClick(m_window.get(), Qt::Key_F11);
  settle();
  ASSERT_TRUE(m_window->presentationMode());
  EXPECT_GE(m_window->rayTreePanel()->font().pointSizeF(), 1.5 * font) << "fonts not scaled";
  EXPECT_EQ(panel.lineScale(), 2.0) << "rays not thicker";
  EXPECT_FALSE(m_window->inspectorPanel()->isVisible()) << "developer panels still shown";
  EXPECT_FALSE(m_window->editPanel()->isVisible());
  EXPECT_TRUE(panel.isVisible());
  // The animation keys: Home, Right steps, Left steps back, End, Space plays.
  m_window->viewWidget()->setFocus();
  QTest::keyClick(m_window.get(), Qt::Key_Home);
  EXPECT_EQ(panel.frame(), 0);
  QTest::keyClick(m_window.get(), Qt::Key_Right);
  const int afterRight = panel.frame();
  EXPECT_GT(afterRight, 0);
  QTest::keyClick(m_window.get(), Qt::Key_Right);
  EXPECT_GT(panel.frame(), afterRight);
  QTest::keyClick(m_window.get(), Qt::Key_Left);
  EXPECT_EQ(panel.frame(), afterRight);
  QTest::keyClick(m_window.get(), Qt::Key_End);
  EXPECT_EQ(panel.frame(), panel.frameCount() - 1);
  QTest::keyClick(m_window.get(), Qt::Key_Home);
  QTest::keyClick(m_window.get(), Qt::Key_Space);
  EXPECT_TRUE(panel.playing());
  const double speed = panel.speed();
  QTest::keyClick(m_window.get(), Qt::Key_Plus);
  EXPECT_GT(panel.speed(), speed);
  QTest::keyClick(m_window.get(), Qt::Key_Space);
  EXPECT_FALSE(panel.playing());
  // F11 again: the layout and the font are back.
  QTest::keyClick(m_window.get(), Qt::Key_F11);
  settle();
  EXPECT_FALSE(m_window->presentationMode());
  EXPECT_EQ(m_window->rayTreePanel()->font().toString(), textBefore);
  EXPECT_EQ(panel.lineScale(), 1.0);
}

// The 3D view is framed for its own shape, also after the window changes it (the layout
// settling after a lesson step, a dock closed): the default view fits the view's aspect. A
// camera the user has turned stays where it is.
TEST_F(MainWindowTest, 20b_TheViewIsFramedAgainWhenItChangesShape) {
  QWidget* w = m_window->viewWidget();
  const auto aspect = [w] { return double(w->width()) / w->height(); };
  const auto expectFramed = [&] {
    const vis::ViewCamera want = vis::defaultViewCamera(m_window->document().scene(), aspect());
    const vis::ViewCamera got = m_window->sceneView().viewCamera();
    EXPECT_LT(glm::length(got.eye - want.eye), 1e-9 * glm::length(want.eye))
        << got.toString() << " against " << want.toString() << " at aspect " << aspect();
    EXPECT_LT(glm::length(got.focalPoint - want.focalPoint), 1e-9);
  };
  expectFramed();
  const double before = aspect();
  m_window->imageTabs()->show();  // the image beside the view: a narrower view
  settle();
  ASSERT_GT(std::abs(aspect() - before), 0.1);
  expectFramed();
  m_window->imageTabs()->hide();
  settle();
  expectFramed();

  // Turned by the user: a change of shape leaves the camera alone.
  drag(QPoint(w->width() / 2, w->height() / 2), QPoint(w->width() / 2 + 80, w->height() / 2));
  const vis::ViewCamera turned = m_window->sceneView().viewCamera();
  m_window->imageTabs()->show();
  settle();
  EXPECT_EQ(m_window->sceneView().viewCamera().eye, turned.eye);
}

TEST_F(MainWindowTest, 21_EveryActionHasATooltipAndTheShortcutTableListsThem) {
  const QList<QStringList> rows = m_window->shortcutTable();
  int withKeys = 0;
  for (QAction* menu : m_window->menuBar()->actions()) {
    if (!menu->menu()) continue;
    for (QAction* a : menu->menu()->actions()) {
      if (a->isSeparator() || a->menu()) continue;
      const QString text = a->text().remove(QLatin1Char('&'));
      EXPECT_FALSE(a->toolTip().isEmpty() || a->toolTip() == text)
          << "no tooltip: " << text.toStdString();
      if (!a->shortcuts().isEmpty()) ++withKeys;
    }
  }
  EXPECT_GE(rows.size(), withKeys) << "the table misses actions with keys";
  bool f11 = false, space = false;
  for (const QStringList& row : rows) {
    f11 = f11 || row[1].contains(QStringLiteral("F11"));
    space = space || row[1].contains(QStringLiteral("Space"));
  }
  EXPECT_TRUE(f11 && space);
}

// The menus come from tables of actions (window/WindowMenus.cpp): an action that needs a
// selection is enabled only while there is one, in the menu and for its shortcut.
TEST_F(MainWindowTest, 22_ActionsOnTheSelectionAreEnabledOnlyWithOne) {
  QAction* remove = nullptr;
  QAction* duplicate = nullptr;
  for (QAction* menu : m_window->menuBar()->actions())
    if (menu->menu())
      for (QAction* a : menu->menu()->actions()) {
        if (a->shortcuts().contains(QKeySequence(QKeySequence::Delete))) remove = a;
        if (a->shortcuts().contains(QKeySequence(Qt::CTRL | Qt::Key_D))) duplicate = a;
      }
  ASSERT_TRUE(remove && duplicate);
  m_window->selectObject(-1);
  EXPECT_FALSE(remove->isEnabled());
  EXPECT_FALSE(duplicate->isEnabled());
  const std::size_t objects = m_window->document().scene().objects.size();
  activate();
  QTest::keyClick(m_window->viewWidget(), Qt::Key_Delete);
  EXPECT_EQ(m_window->document().scene().objects.size(), objects);
  m_window->selectObject(0);
  EXPECT_TRUE(remove->isEnabled());
  EXPECT_TRUE(duplicate->isEnabled());
  activate();
  QTest::keyClick(m_window->viewWidget(), Qt::Key_Delete);
  EXPECT_EQ(m_window->document().scene().objects.size(), objects - 1) << "Del deletes it";
  EXPECT_EQ(m_window->selectedObject(), -1);
  EXPECT_FALSE(remove->isEnabled()) << "nothing selected after the delete";
}

// Issue 33 item 2: opening a scene file starts with nothing selected. The old selection's
// row number named another object of the new scene (outlined, and Del would delete it).
TEST_F(MainWindowTest, 23_OpeningASceneFileClearsTheSelection) {
  m_window->selectObject(0);
  ASSERT_EQ(m_window->selectedObject(), 0);
  const QString cornell = QString::fromLatin1(RAYLAB_SOURCE_DIR) + "/lessons/scenes/cornell.json";
  ASSERT_TRUE(m_window->openFile(cornell, false));
  settle();
  EXPECT_EQ(m_window->selectedObject(), -1);
  EXPECT_EQ(m_window->sceneView().highlighted(), -1);
  EXPECT_EQ(m_window->objectList()->currentRow(), -1);
}

}  // namespace
}  // namespace raylab::app
