#include "raylab/core/Box.h"
#include "raylab/core/Quad.h"
#include "raylab/core/Scene.h"
#include "raylab/core/Sphere.h"
#include "raylab/core/Transform.h"

namespace raylab {

Scene defaultScene() {
  Scene scene;
  scene.name = "RayLab default scene";
  scene.nameZh = "RayLab 默认场景";

  // Materials: the original course program's red sphere, blue cube and flesh-coloured
  // light, grey walls.
  const Vec3 flesh(1.0, 0.8, 0.65);
  auto makeMaterial = [](std::string name, std::string nameZh, const Vec3& colour,
                         const Vec3& emission) {
    Material m;
    m.name = std::move(name);
    m.nameZh = std::move(nameZh);
    m.colour = colour;
    m.emission = emission;
    return m;
  };
  scene.materials = {
      makeMaterial("red", "红色半反半透", {0.80, 0.10, 0.10}, Vec3(0.0)),
      makeMaterial("blue", "蓝色光泽漆", {0.10, 0.20, 0.80}, Vec3(0.0)),
      makeMaterial("light", "发光体", flesh, 8.0 * flesh),
      makeMaterial("wall", "墙面", {0.75, 0.75, 0.75}, Vec3(0.0)),
  };
  // The original program's two demonstrations: its red sphere is a mirror material that
  // reflects part of the light and refracts the rest (its reflection_rate, refraction_rate
  // and index of refraction), and its blue cube is Phong glossy, so a ray the sphere
  // reflects onto the cube fans out into glossy rays.
  Material& mirror = scene.materials[0];
  mirror.type = MaterialType::Mirror;
  mirror.colour = {0.95, 0.35, 0.35};
  mirror.reflectionRate = 0.5;
  mirror.refractionRate = 0.5;
  mirror.ior = 1.5;
  Material& glossy = scene.materials[1];
  glossy.type = MaterialType::Glossy;
  glossy.exponent = 40.0;
  glossy.specular = 0.5;
  const int red = 0, blue = 1, light = 2, wall = 3;

  // The room: x in [-5, 5], y in [0, 6], z in [-6, 4], open towards +z. Quad normals
  // (edgeU x edgeV) point into the room.
  // Each with its Chinese display name (SceneObject::nameZh).
  auto add = [&scene](std::string name, std::string nameZh, std::unique_ptr<Shape> shape,
                      int material) {
    scene.objects.emplace_back(std::move(name), std::move(shape), material);
    scene.objects.back().nameZh = std::move(nameZh);
  };
  add("floor", "地板", std::make_unique<Quad>(Point3(-5, 0, 4), Vec3(10, 0, 0), Vec3(0, 0, -10)),
      wall);
  add("ceiling", "天花板",
      std::make_unique<Quad>(Point3(-5, 6, -6), Vec3(10, 0, 0), Vec3(0, 0, 10)), wall);
  add("back wall", "后墙", std::make_unique<Quad>(Point3(-5, 0, -6), Vec3(10, 0, 0), Vec3(0, 6, 0)),
      wall);
  add("left wall", "左墙", std::make_unique<Quad>(Point3(-5, 0, 4), Vec3(0, 0, -10), Vec3(0, 6, 0)),
      wall);
  add("right wall", "右墙", std::make_unique<Quad>(Point3(5, 0, -6), Vec3(0, 0, 10), Vec3(0, 6, 0)),
      wall);

  // The original course program's objects.
  add("red sphere", "红色球体", std::make_unique<Sphere>(Point3(-1.6, 1.2, -2.2), 1.2, 24, 32),
      red);
  auto cube = std::make_unique<Box>(Point3(0.0), Vec3(2.0));
  // Turn the cube 30 degrees about y, then lift it onto the floor (rotation first).
  cube->apply((Transform::translate({1.7, 1.0, -1.5}) * Transform::rotate(radians(30.0), {0, 1, 0}))
                  .matrix());
  add("blue cube", "蓝色立方体", std::move(cube), blue);
  add("light", "光源盒", std::make_unique<Box>(Point3(0.0, 5.2, -2.0), Vec3(1.2, 0.4, 1.2)), light);

  // A camera inside the room's open front, looking at the objects.
  scene.camera.position = {0.0, 2.4, 3.5};
  scene.camera.lookAt = {0.0, 1.4, -2.0};
  scene.camera.up = {0.0, 1.0, 0.0};
  scene.camera.verticalFov = 50.0;
  scene.camera.width = 320;
  scene.camera.height = 240;
  return scene;
}

}  // namespace raylab
