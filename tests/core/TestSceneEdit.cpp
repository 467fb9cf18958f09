// Scene edits as the window makes them (SceneEdit.h): each is checked by the scene
// loader's own rules and refused with its message, transforms act about the object's
// centre, and an edit undone by its inverse saves the same file.
#include "raylab/core/SceneEdit.h"

#include "raylab/core/Box.h"
#include "raylab/core/Camera.h"
#include "raylab/core/SceneIO.h"
#include "raylab/core/Sphere.h"
#include "raylab/core/Transform.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include <string>

namespace raylab {
namespace {

const std::string kOrigin = "classroom.json";

/// The loader's message for an edit, or "" when the edit is accepted.
template <typename Edit>
std::string refusal(Edit edit) {
  try {
    edit();
  } catch (const SceneIO::LoadError& e) {
    return e.what();
  }
  return "";
}

TEST(SceneEdit, 01_RotateTheCube90DegreesAboutZ) {
  const Scene scene = defaultScene();
  const int cube = scene.findObject("blue cube");
  ASSERT_GE(cube, 0);
  const auto& before = static_cast<const Box&>(*scene.objects[std::size_t(cube)].shape);
  const Point3 c = before.centre();
  const Scene turned = edit::rotateObject(scene, cube, 90.0, Vec3(0, 0, 1), kOrigin);
  const auto& after = static_cast<const Box&>(*turned.objects[std::size_t(cube)].shape);
  // Every vertex goes where a quarter turn about z through the centre puts it:
  // (x, y, z) - c -> (-y, x, z) + c.
  const auto from = before.vertices();
  const auto to = after.vertices();
  for (int k = 0; k < 8; ++k) {
    const Vec3 d = from[std::size_t(k)] - c;
    const Point3 expected = c + Vec3(-d.y, d.x, d.z);
    EXPECT_NEAR(glm::length(to[std::size_t(k)] - expected), 0.0, 1e-12) << "vertex " << k;
  }
  // Turning back puts every vertex back (to rounding); the other objects never moved.
  const Scene back = edit::rotateObject(turned, cube, -90.0, Vec3(0, 0, 1), kOrigin);
  const auto again = static_cast<const Box&>(*back.objects[std::size_t(cube)].shape).vertices();
  for (int k = 0; k < 8; ++k)
    EXPECT_NEAR(glm::length(again[std::size_t(k)] - from[std::size_t(k)]), 0.0, 1e-12);
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    if (int(i) == cube) continue;
    EXPECT_EQ(turned.objects[i].shape->bounds().centre(),
              scene.objects[i].shape->bounds().centre());
  }
  EXPECT_EQ(turned.objects.size(), scene.objects.size());
}

TEST(SceneEdit, 02_InvalidValuesAreRefusedWithTheLoadersMessage) {
  const Scene scene = defaultScene();
  const int sphere = scene.findObject("red sphere");
  EXPECT_EQ(refusal([&] { edit::rotateObject(scene, sphere, 30.0, Vec3(0.0), kOrigin); }),
            "classroom.json: at /objects/" + std::to_string(sphere) +
                "/transform/1/rotate/axis: vector must not be zero (it gives a direction)")
      << "a zero rotation axis";
  EXPECT_NE(refusal([&] {
              edit::setValue(scene, "/objects/" + std::to_string(sphere) + "/shape/radius", "0",
                             kOrigin);
            }).find("/shape/radius: radius must be positive"),
            std::string::npos);
  EXPECT_EQ(refusal([&] { edit::setValue(scene, "/materials/0/ior", "0", kOrigin); }),
            "classroom.json: at /materials/0/ior: ior (index of refraction) must be positive");
  EXPECT_NE(refusal([&] {
              edit::scaleObject(scene, sphere, Vec3(1, 0, 1), kOrigin);
            }).find("scale factors must not be zero"),
            std::string::npos);
  EXPECT_NE(refusal([&] { edit::renameObject(scene, sphere, "blue cube", kOrigin); }), "");
  EXPECT_NE(refusal([&] {
              edit::setValue(scene, "/materials/99/ior", "1.5", kOrigin);
            }).find("no such place"),
            std::string::npos);
  // Found by fuzzing `--set` (FuzzSet): an empty name where an array's index goes made
  // the JSON library throw past the refusal, and the command line abort.
  EXPECT_NE(refusal([&] {
              edit::setValue(scene, "/materials///5/r", "0e20", kOrigin);
            }).find("no such place"),
            std::string::npos);
  EXPECT_NE(refusal([&] {
              edit::setValue(scene, "/camera/vertical_fov", "wide", kOrigin);
            }).find("not a JSON value"),
            std::string::npos);
}

TEST(SceneEdit, 03_AValueSetAndSetBackSavesTheSameFile) {
  const Scene scene = defaultScene();
  const std::string original = SceneIO::serialize(scene);
  const std::string ior = edit::valueAt(scene, "/camera/vertical_fov", kOrigin);
  const Scene wide = edit::setValue(scene, "/camera/vertical_fov", "70", kOrigin);
  EXPECT_EQ(wide.camera.verticalFov, 70.0);
  EXPECT_NE(SceneIO::serialize(wide), original);
  const Scene back = edit::setValue(wide, "/camera/vertical_fov", ior, kOrigin);
  EXPECT_EQ(SceneIO::serialize(back), original);
  // A material's parameter: every object made of it changes.
  const Scene glossy = edit::setValue(scene, "/materials/1/type", "\"glossy\"", kOrigin);
  EXPECT_EQ(glossy.materials[1].type, MaterialType::Glossy);
}

// A value of the file reached through its own keys: the size of a box the file turns and
// moves with transform steps is the size before them, and the steps still apply after it.
TEST(SceneEdit, 03b_AValueBeneathTransformStepsIsTheFilesValue) {
  const Scene scene = SceneIO::parse(R"({"raylab_scene": 2,
    "materials": [{"name": "m"}],
    "objects": [{"name": "b", "material": "m",
      "shape": {"type": "box", "centre": [0, 0, 0], "size": [1, 1, 1]},
      "transform": [{"rotate": {"axis": [0, 0, 1], "degrees": 90}}, {"translate": [5, 0, 0]}]}]})",
                                     kOrigin);
  EXPECT_EQ(edit::valueAt(scene, "/objects/0/shape/size", kOrigin), "[1,1,1]");
  EXPECT_EQ(edit::valueAt(scene, "/objects/0/transform/1/translate", kOrigin), "[5,0,0]");
  const Scene bigger = edit::setValue(scene, "/objects/0/shape/size", "[2, 4, 6]", kOrigin);
  const auto& box = static_cast<const Box&>(*bigger.objects[0].shape);
  EXPECT_NEAR(glm::length(box.centre() - Point3(5, 0, 0)), 0.0, 1e-12);
  // Sizes (2, 4, 6) turned a quarter about z: x and y swap.
  const Bounds3 b = box.bounds();
  EXPECT_NEAR(b.extent().x, 4.0, 1e-9);
  EXPECT_NEAR(b.extent().y, 2.0, 1e-9);
  EXPECT_NEAR(b.extent().z, 6.0, 1e-9);
  // A move in the window right after the file's own translation adds to it (the same
  // transform, one step shorter); the file keeps the steps before it.
  const Scene moved = edit::translateObject(bigger, 0, Vec3(0, 1, 0), kOrigin);
  EXPECT_EQ(edit::valueAt(moved, "/objects/0/transform/0/rotate/degrees", kOrigin), "90");
  EXPECT_EQ(edit::valueAt(moved, "/objects/0/transform/1/translate", kOrigin), "[5.0,1.0,0.0]");
  const Scene twice = edit::translateObject(moved, 0, Vec3(0.5, 1, 0), kOrigin);
  EXPECT_EQ(edit::valueAt(twice, "/objects/0/transform/1/translate", kOrigin), "[5.5,2.0,0.0]");
  EXPECT_THROW(edit::valueAt(twice, "/objects/0/transform/2", kOrigin), SceneIO::LoadError);
  // Turned twice about the same axis: one turn of the sum, about the same centre.
  const Scene turned = edit::rotateObject(twice, 0, 30.0, Vec3(0, 1, 0), kOrigin);
  const Scene turnedTwice = edit::rotateObject(turned, 0, 15.0, Vec3(0, 1, 0), kOrigin);
  EXPECT_EQ(edit::valueAt(turnedTwice, "/objects/0/transform/3/rotate/degrees", kOrigin), "45.0");
  EXPECT_THROW(edit::valueAt(turnedTwice, "/objects/0/transform/5", kOrigin), SceneIO::LoadError);
  const Scene once = edit::rotateObject(twice, 0, 45.0, Vec3(0, 1, 0), kOrigin);
  const auto& summed = static_cast<const Box&>(*turnedTwice.objects[0].shape);
  const auto& single = static_cast<const Box&>(*once.objects[0].shape);
  EXPECT_NEAR(glm::length(summed.centre() - single.centre()), 0.0, 1e-12);
  EXPECT_NEAR(glm::length(summed.axis(0) - single.axis(0)), 0.0, 1e-12);
  // About another axis: a new turn.
  const Scene other = edit::rotateObject(turnedTwice, 0, 10.0, Vec3(1, 0, 0), kOrigin);
  EXPECT_EQ(edit::valueAt(other, "/objects/0/transform/6/rotate/degrees", kOrigin), "10.0");
}

TEST(SceneEdit, 04_DeleteDuplicateRenameAndTranslate) {
  const Scene scene = defaultScene();
  const int sphere = scene.findObject("red sphere");
  const Scene fewer = edit::removeObject(scene, sphere, kOrigin);
  EXPECT_EQ(fewer.objects.size(), scene.objects.size() - 1);
  EXPECT_LT(fewer.findObject("red sphere"), 0);

  const Scene more = edit::duplicateObject(scene, sphere, Vec3(0.5, 0, 0), kOrigin);
  ASSERT_EQ(more.objects.size(), scene.objects.size() + 1);
  EXPECT_EQ(more.objects.back().name, "red sphere copy");
  const auto& copy = static_cast<const Sphere&>(*more.objects.back().shape);
  const auto& ball = static_cast<const Sphere&>(*scene.objects[std::size_t(sphere)].shape);
  EXPECT_NEAR(glm::length(copy.centre() - (ball.centre() + Vec3(0.5, 0, 0))), 0.0, 1e-12);
  EXPECT_EQ(edit::duplicateObject(more, sphere, Vec3(1, 0, 0), kOrigin).objects.back().name,
            "red sphere copy 2");

  const Scene renamed = edit::renameObject(scene, sphere, "mirror ball", kOrigin);
  EXPECT_EQ(renamed.objects[std::size_t(sphere)].name, "mirror ball");

  const Scene moved = edit::translateObject(scene, sphere, Vec3(0, 1, 0), kOrigin);
  const auto& up = static_cast<const Sphere&>(*moved.objects[std::size_t(sphere)].shape);
  EXPECT_NEAR(glm::length(up.centre() - (ball.centre() + Vec3(0, 1, 0))), 0.0, 1e-12);
}

TEST(SceneEdit, 04b_ManyAlternatingEditsKeepTheEntryShort) {
  // Issue 38: moves and turns that alternate cannot merge, and each edit re-read every
  // step before it (2,000 took over 60 s). Past 48 steps the object's steps are folded.
  const Scene scene = defaultScene();
  const int cube = scene.findObject("blue cube");
  Scene edited = scene;
  Vec3 moved(0.0);
  for (int i = 0; i < 200; ++i) {
    edited = i % 2 == 0 ? edit::translateObject(edited, cube, Vec3(0.01, 0, 0), kOrigin)
                        : edit::rotateObject(edited, cube, 3.0, Vec3(0, 1, 0), kOrigin);
    if (i % 2 == 0) moved.x += 0.01;
  }
  const nlohmann::json saved = nlohmann::json::parse(SceneIO::serialize(edited, ""));
  const nlohmann::json& entry = saved["objects"][std::size_t(cube)];
  EXPECT_LE(entry.value("transform", nlohmann::json::array()).size(), 51u) << entry.dump();
  // The cube is where the edits put it: moved by the sum of the moves, turned about its
  // own centre (which turns do not move) by 100 x 3 degrees.
  const auto& before = static_cast<const Box&>(*scene.objects[std::size_t(cube)].shape);
  const auto& after = static_cast<const Box&>(*edited.objects[std::size_t(cube)].shape);
  EXPECT_NEAR(glm::length(after.centre() - (before.centre() + moved)), 0.0, 1e-9);
  const Mat4 turn = glm::rotate(Mat4(1.0), glm::radians(300.0), Vec3(0, 1, 0));
  const Mat4 expected = before.worldFromBox().matrix();
  const Mat4 actual = after.worldFromBox().matrix();
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r)
      EXPECT_NEAR(actual[c][r], (turn * expected)[c][r], 1e-9) << c << " " << r;
}

TEST(SceneEdit, 05_AddedObjectsAreWhereTheCameraLooks) {
  const Scene scene = defaultScene();
  const Camera camera(scene.camera);
  for (edit::NewShape shape : {edit::NewShape::Sphere, edit::NewShape::Box, edit::NewShape::Quad,
                               edit::NewShape::Triangle, edit::NewShape::Plane}) {
    const Scene added = edit::addShape(scene, shape, kOrigin);
    ASSERT_EQ(added.objects.size(), scene.objects.size() + 1);
    const SceneObject& object = added.objects.back();
    EXPECT_EQ(added.materials[std::size_t(object.material)].type, MaterialType::Diffuse);
    // The camera ray through the image centre meets the new object (the plane: anywhere).
    Ray ray = camera.generateRay(Vec2(scene.camera.width / 2.0, scene.camera.height / 2.0),
                                 Vec2(0.5), 0.0);
    EXPECT_TRUE(object.shape->intersect(ray).has_value()) << object.name;
  }
  EXPECT_EQ(edit::addShape(edit::addShape(scene, edit::NewShape::Sphere, kOrigin),
                           edit::NewShape::Sphere, kOrigin)
                .objects.back()
                .name,
            "sphere 2");
  const Scene lit = edit::addPointLight(scene, kOrigin);
  ASSERT_EQ(lit.pointLights.size(), scene.pointLights.size() + 1);
  EXPECT_GT(lit.pointLights.back().position.y, scene.camera.lookAt.y);
}

TEST(SceneEdit, 06_EveryShapeIsAddedByItsWordAndSavedAsItReads) {
  // The shapes that can be added, from the table of shape descriptors (not a mesh: it comes
  // from its file), in the order of ShapeKind.
  EXPECT_EQ(edit::newShapeWordList(), "sphere, box, plane, quad or triangle");
  EXPECT_FALSE(edit::newShapeKind("mesh").has_value());
  EXPECT_FALSE(edit::newShapeKind("cylinder").has_value());
  const Scene scene = defaultScene();
  for (const std::string word : {"sphere", "box", "plane", "quad", "triangle"}) {
    const std::optional<edit::NewShape> kind = edit::newShapeKind(word);
    ASSERT_TRUE(kind.has_value()) << word;
    EXPECT_EQ(toString(*kind), word);
    const Scene added = edit::addShape(scene, *kind, kOrigin);
    EXPECT_EQ(added.objects.back().shape->kind(), *kind) << word;
    EXPECT_EQ(added.objects.back().name, word);
    // Written by the shape's own writer, read by its reader, written again: the same bytes.
    const std::string text = SceneIO::serialize(added);
    EXPECT_NE(text.find("\"type\": \"" + word + "\""), std::string::npos) << text;
    EXPECT_EQ(SceneIO::serialize(SceneIO::parse(text, "added.json")), text) << word;
  }
}

}  // namespace
}  // namespace raylab
