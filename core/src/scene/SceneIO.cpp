#include "raylab/core/SceneIO.h"

#include "raylab/core/Box.h"
#include "raylab/core/Plane.h"
#include "raylab/core/Quad.h"
#include "raylab/core/Sphere.h"
#include "raylab/core/Transform.h"
#include "raylab/core/Triangle.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <sys/stat.h>
#include <unistd.h>

namespace raylab {

namespace {

using nlohmann::json;

/// Reads one scene document and remembers the file name for every message.
class Reader {
 public:
  explicit Reader(std::string origin) : m_origin(std::move(origin)) {}

  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw SceneIO::LoadError(m_origin + ": at " + (path.empty() ? "/" : path) + ": " + what);
  }

  const json& member(const json& j, const std::string& path, const char* key) const {
    if (!j.is_object()) fail(path, "expected an object");
    const auto it = j.find(key);
    if (it == j.end()) fail(path, std::string("missing \"") + key + "\"");
    return *it;
  }

  double number(const json& j, const std::string& path) const {
    if (!j.is_number()) fail(path, "expected a number, got " + j.dump());
    const double v = j.get<double>();
    if (!std::isfinite(v)) fail(path, "number must be finite");
    return v;
  }

  int integer(const json& j, const std::string& path) const {
    if (!j.is_number_integer()) fail(path, "expected an integer, got " + j.dump());
    return j.get<int>();
  }

  std::string string(const json& j, const std::string& path) const {
    if (!j.is_string()) fail(path, "expected a string, got " + j.dump());
    return j.get<std::string>();
  }

  Vec3 vec3(const json& j, const std::string& path) const {
    if (!j.is_array() || j.size() != 3) fail(path, "expected [x, y, z], got " + j.dump());
    return {number(j[0], path + "/0"), number(j[1], path + "/1"), number(j[2], path + "/2")};
  }

  Vec3 nonZero(const json& j, const std::string& path) const {
    const Vec3 v = vec3(j, path);
    if (v == Vec3(0.0)) fail(path, "vector must not be zero (it gives a direction)");
    return v;
  }

  Mat4 matrix(const json& j, const std::string& path) const {
    if (!j.is_array() || j.size() != 4) fail(path, "expected 4 rows of 4 numbers");
    Mat4 m(1.0);
    for (int r = 0; r < 4; ++r) {
      const std::string rp = path + "/" + std::to_string(r);
      if (!j[r].is_array() || j[r].size() != 4) fail(rp, "expected a row of 4 numbers");
      for (int c = 0; c < 4; ++c) m[c][r] = number(j[r][c], rp + "/" + std::to_string(c));
    }
    if (!isAffine(m)) fail(path, "last row must be [0, 0, 0, 1] (an affine transform)");
    if (glm::determinant(Mat3(m)) == 0.0) fail(path, "matrix is singular");
    return m;
  }

  std::unique_ptr<Shape> shape(const json& j, const std::string& path) const {
    const std::string type = string(member(j, path, "type"), path + "/type");
    try {
      if (type == "sphere") {
        const double radius = number(member(j, path, "radius"), path + "/radius");
        if (radius <= 0.0)
          fail(path + "/radius", "radius must be positive, got " + j["radius"].dump());
        const int m = j.contains("m") ? integer(j["m"], path + "/m") : 24;
        const int n = j.contains("n") ? integer(j["n"], path + "/n") : 24;
        if (m < 2) fail(path + "/m", "m (polar slices) must be at least 2");
        if (n < 3) fail(path + "/n", "n (azimuthal slices) must be at least 3");
        return std::make_unique<Sphere>(vec3(member(j, path, "centre"), path + "/centre"), radius,
                                        m, n);
      }
      if (type == "box") {
        if (j.contains("matrix"))
          return std::make_unique<Box>(Transform(matrix(j["matrix"], path + "/matrix")));
        const Vec3 centre = vec3(member(j, path, "centre"), path + "/centre");
        const Vec3 size = vec3(member(j, path, "size"), path + "/size");
        for (int i = 0; i < 3; ++i)
          if (size[i] <= 0.0)
            fail(path + "/size/" + std::to_string(i), "box size must be positive");
        if (!j.contains("axes")) return std::make_unique<Box>(centre, size);
        const json& axes = j["axes"];
        if (!axes.is_array() || axes.size() != 3)
          fail(path + "/axes", "expected three axes [x, y, z]");
        Vec3 a[3];
        for (int i = 0; i < 3; ++i) a[i] = nonZero(axes[i], path + "/axes/" + std::to_string(i));
        return std::make_unique<Box>(centre, size, a[0], a[1], a[2]);
      }
      if (type == "plane")
        return std::make_unique<Plane>(vec3(member(j, path, "point"), path + "/point"),
                                       nonZero(member(j, path, "normal"), path + "/normal"));
      if (type == "quad")
        return std::make_unique<Quad>(vec3(member(j, path, "corner"), path + "/corner"),
                                      nonZero(member(j, path, "u"), path + "/u"),
                                      nonZero(member(j, path, "v"), path + "/v"));
      if (type == "triangle") {
        const json& v = member(j, path, "vertices");
        if (!v.is_array() || v.size() != 3) fail(path + "/vertices", "expected three points");
        return std::make_unique<Triangle>(vec3(v[0], path + "/vertices/0"),
                                          vec3(v[1], path + "/vertices/1"),
                                          vec3(v[2], path + "/vertices/2"));
      }
    } catch (const Shape::InvalidGeometry& e) {
      fail(path, e.what());
    }
    fail(path + "/type",
         "unknown shape type \"" + type + "\" (expected sphere, box, plane, quad or triangle)");
  }

  Mat4 transform(const json& steps, const std::string& path) const {
    if (!steps.is_array()) fail(path, "expected a list of steps");
    Mat4 m(1.0);
    for (std::size_t i = 0; i < steps.size(); ++i) {
      const std::string sp = path + "/" + std::to_string(i);
      const json& s = steps[i];
      if (!s.is_object() || s.size() != 1)
        fail(sp, "a step is one of translate, scale, rotate, matrix");
      Mat4 step(1.0);
      if (s.contains("translate")) {
        step = Transform::translate(vec3(s["translate"], sp + "/translate")).matrix();
      } else if (s.contains("scale")) {
        const Vec3 f = vec3(s["scale"], sp + "/scale");
        if (f.x == 0.0 || f.y == 0.0 || f.z == 0.0)
          fail(sp + "/scale", "scale factors must not be zero");
        step = Transform::scale(f).matrix();
      } else if (s.contains("rotate")) {
        const json& r = s["rotate"];
        const Vec3 axis = nonZero(member(r, sp + "/rotate", "axis"), sp + "/rotate/axis");
        const double degrees = number(member(r, sp + "/rotate", "degrees"), sp + "/rotate/degrees");
        step = Transform::rotate(radians(degrees), axis).matrix();
      } else if (s.contains("matrix")) {
        step = matrix(s["matrix"], sp + "/matrix");
      } else {
        fail(sp,
             "unknown step " + s.begin().key() + " (expected translate, scale, rotate, matrix)");
      }
      m = step * m;  // later steps apply after earlier ones
    }
    return m;
  }

  Scene scene(const json& root) const {
    if (!root.is_object()) fail("", "a scene file is a JSON object");
    if (!root.contains("raylab_scene"))
      fail("", "missing \"raylab_scene\": <version> (is this a RayLab scene file?)");
    const int version = integer(root["raylab_scene"], "/raylab_scene");
    if (version != SceneIO::kVersion)
      fail("/raylab_scene", "unsupported version " + std::to_string(version) +
                                " (this RayLab reads version " + std::to_string(SceneIO::kVersion) +
                                ")");
    Scene scene;
    scene.name = root.contains("name") ? string(root["name"], "/name") : "untitled";

    const json& materials = member(root, "", "materials");
    if (!materials.is_array()) fail("/materials", "expected a list");
    for (std::size_t i = 0; i < materials.size(); ++i) {
      const std::string p = "/materials/" + std::to_string(i);
      const json& j = materials[i];
      Material m;
      m.name = string(member(j, p, "name"), p + "/name");
      if (scene.findMaterial(m.name) >= 0)
        fail(p + "/name", "duplicate material \"" + m.name + "\"");
      if (j.contains("colour")) m.colour = vec3(j["colour"], p + "/colour");
      if (j.contains("emission")) m.emission = vec3(j["emission"], p + "/emission");
      if (j.contains("opacity")) m.opacity = number(j["opacity"], p + "/opacity");
      for (int c = 0; c < 3; ++c) {
        if (m.colour[c] < 0.0 || m.colour[c] > 1.0)
          fail(p + "/colour", "colour components must be in [0, 1]");
        if (m.emission[c] < 0.0) fail(p + "/emission", "emission must not be negative");
      }
      if (m.opacity < 0.0 || m.opacity > 1.0) fail(p + "/opacity", "opacity must be in [0, 1]");
      scene.materials.push_back(m);
    }

    const json& objects = member(root, "", "objects");
    if (!objects.is_array()) fail("/objects", "expected a list");
    for (std::size_t i = 0; i < objects.size(); ++i) {
      const std::string p = "/objects/" + std::to_string(i);
      const json& j = objects[i];
      SceneObject o;
      o.name = string(member(j, p, "name"), p + "/name");
      if (scene.findObject(o.name) >= 0) fail(p + "/name", "duplicate object \"" + o.name + "\"");
      const std::string material = string(member(j, p, "material"), p + "/material");
      o.material = scene.findMaterial(material);
      if (o.material < 0) fail(p + "/material", "unknown material \"" + material + "\"");
      o.shape = shape(member(j, p, "shape"), p + "/shape");
      if (j.contains("transform")) {
        try {
          o.shape->apply(transform(j["transform"], p + "/transform"));
        } catch (const Shape::InvalidGeometry& e) {
          fail(p + "/transform", e.what());
        }
      }
      scene.objects.push_back(std::move(o));
    }

    if (root.contains("camera")) {
      const json& c = root["camera"];
      CameraSpec& cam = scene.camera;
      if (c.contains("position")) cam.position = vec3(c["position"], "/camera/position");
      if (c.contains("look_at")) cam.lookAt = vec3(c["look_at"], "/camera/look_at");
      if (c.contains("up")) cam.up = nonZero(c["up"], "/camera/up");
      if (c.contains("vertical_fov"))
        cam.verticalFov = number(c["vertical_fov"], "/camera/vertical_fov");
      if (c.contains("width")) cam.width = integer(c["width"], "/camera/width");
      if (c.contains("height")) cam.height = integer(c["height"], "/camera/height");
      if (cam.position == cam.lookAt) fail("/camera/look_at", "camera looks at its own position");
      if (glm::length(glm::cross(cam.lookAt - cam.position, cam.up)) == 0.0)
        fail("/camera/up", "up is parallel to the viewing direction");
      if (!(cam.verticalFov > 0.0 && cam.verticalFov < 180.0))
        fail("/camera/vertical_fov", "vertical_fov must be in (0, 180) degrees");
      if (cam.width < 1 || cam.height < 1 || cam.width > 16384 || cam.height > 16384)
        fail("/camera", "width and height must be in [1, 16384]");
    }
    return scene;
  }

 private:
  std::string m_origin;
};

using ojson = nlohmann::ordered_json;

ojson toJson(const Vec3& v) { return ojson::array({v.x, v.y, v.z}); }

ojson toJson(const Mat4& m) {
  ojson rows = ojson::array();
  for (int r = 0; r < 4; ++r) rows.push_back(ojson::array({m[0][r], m[1][r], m[2][r], m[3][r]}));
  return rows;
}

/// Pretty JSON for people: objects one member per line, arrays of scalars on one line.
void prettyPrint(const ojson& j, int indent, std::string& out) {
  const auto scalarArray = [](const ojson& a) {
    for (const ojson& e : a)
      if (e.is_structured() &&
          !(e.is_array() && e.size() <= 4 &&
            std::all_of(e.begin(), e.end(), [](const ojson& x) { return x.is_primitive(); })))
        return false;
    return true;
  };
  const std::string pad(indent + 2, ' ');
  if (j.is_object() && !j.empty()) {
    out += "{\n";
    std::size_t i = 0;
    for (auto it = j.begin(); it != j.end(); ++it, ++i) {
      out += pad + ojson(it.key()).dump() + ": ";
      prettyPrint(it.value(), indent + 2, out);
      out += i + 1 < j.size() ? ",\n" : "\n";
    }
    out += std::string(indent, ' ') + "}";
  } else if (j.is_array() && !j.empty() && !scalarArray(j)) {
    out += "[\n";
    for (std::size_t i = 0; i < j.size(); ++i) {
      out += pad;
      prettyPrint(j[i], indent + 2, out);
      out += i + 1 < j.size() ? ",\n" : "\n";
    }
    out += std::string(indent, ' ') + "]";
  } else if (j.is_array()) {
    out += "[";
    for (std::size_t i = 0; i < j.size(); ++i) {
      out += i ? ", " : "";
      prettyPrint(j[i], indent, out);
    }
    out += "]";
  } else {
    out += j.dump();
  }
}

ojson shapeToJson(const Shape& shape, ojson& transform) {
  switch (shape.kind()) {
    case ShapeKind::Sphere: {
      const auto& s = static_cast<const Sphere&>(shape);
      if (!s.worldFromObject().isIdentity())
        transform = ojson::array({ojson{{"matrix", toJson(s.worldFromObject().matrix())}}});
      return {{"type", "sphere"},
              {"centre", toJson(s.centre())},
              {"radius", s.radius()},
              {"m", s.m()},
              {"n", s.n()}};
    }
    case ShapeKind::Box: {
      const auto& b = static_cast<const Box&>(shape);
      const Box readable(b.centre(), b.size(), b.axis(0), b.axis(1), b.axis(2));
      // Prefer centre/size/axes; fall back to the exact matrix when they do not
      // reproduce the box bit for bit.
      if (readable.worldFromBox().matrix() == b.worldFromBox().matrix()) {
        ojson box = {{"type", "box"}, {"centre", toJson(b.centre())}, {"size", toJson(b.size())}};
        if (b.axis(0) != Vec3(1, 0, 0) || b.axis(1) != Vec3(0, 1, 0) || b.axis(2) != Vec3(0, 0, 1))
          box["axes"] = ojson::array({toJson(b.axis(0)), toJson(b.axis(1)), toJson(b.axis(2))});
        return box;
      }
      return {{"type", "box"}, {"matrix", toJson(b.worldFromBox().matrix())}};
    }
    case ShapeKind::Plane: {
      const auto& p = static_cast<const Plane&>(shape);
      return {{"type", "plane"}, {"point", toJson(p.point())}, {"normal", toJson(p.planeNormal())}};
    }
    case ShapeKind::Quad: {
      const auto& q = static_cast<const Quad&>(shape);
      return {{"type", "quad"},
              {"corner", toJson(q.corner())},
              {"u", toJson(q.edgeU())},
              {"v", toJson(q.edgeV())}};
    }
    case ShapeKind::Triangle: {
      const auto& t = static_cast<const Triangle&>(shape);
      return {{"type", "triangle"},
              {"vertices",
               ojson::array({toJson(t.vertex(0)), toJson(t.vertex(1)), toJson(t.vertex(2))})}};
    }
    case ShapeKind::TriangleMesh:
      break;
  }
  throw SceneIO::SaveError(std::string("cannot save shape of kind ") + toString(shape.kind()));
}

/// 1-based line and column of a byte offset.
std::pair<int, int> lineColumn(const std::string& text, std::size_t offset) {
  int line = 1, column = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return {line, column};
}

}  // namespace

Scene SceneIO::parse(const std::string& text, const std::string& origin) {
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& e) {
    const auto [line, column] = lineColumn(text, e.byte > 0 ? e.byte - 1 : 0);
    std::string what = e.what();
    // nlohmann's message starts with "[json.exception.parse_error.101] parse error at
    // line L, column C: "; keep only the explanation.
    const auto colon = what.find(": ");
    if (colon != std::string::npos) what = what.substr(colon + 2);
    throw LoadError(origin + ":" + std::to_string(line) + ":" + std::to_string(column) +
                    ": JSON syntax error: " + what);
  }
  return Reader(origin).scene(root);
}

Scene SceneIO::load(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw LoadError(path + ": cannot open scene file (does it exist and is it readable?)");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw LoadError(path + ": read error");
  return parse(text.str(), path);
}

std::string SceneIO::serialize(const Scene& scene) {
  ojson root;
  root["raylab_scene"] = kVersion;
  root["name"] = scene.name;
  root["materials"] = ojson::array();
  for (const Material& m : scene.materials)
    root["materials"].push_back({{"name", m.name},
                                 {"colour", toJson(m.colour)},
                                 {"emission", toJson(m.emission)},
                                 {"opacity", m.opacity}});
  root["objects"] = ojson::array();
  for (const SceneObject& o : scene.objects) {
    if (!o.shape) throw SaveError("object \"" + o.name + "\" has no shape");
    if (o.material < 0 || o.material >= static_cast<int>(scene.materials.size()))
      throw SaveError("object \"" + o.name + "\" refers to a missing material");
    ojson transform;
    ojson object = {{"name", o.name},
                    {"material", scene.materials[o.material].name},
                    {"shape", shapeToJson(*o.shape, transform)}};
    if (!transform.is_null()) object["transform"] = transform;
    root["objects"].push_back(object);
  }
  const CameraSpec& c = scene.camera;
  root["camera"] = {{"position", toJson(c.position)},
                    {"look_at", toJson(c.lookAt)},
                    {"up", toJson(c.up)},
                    {"vertical_fov", c.verticalFov},
                    {"width", c.width},
                    {"height", c.height}};
  // nlohmann prints doubles with enough digits to round-trip exactly.
  std::string text;
  prettyPrint(root, 0, text);
  return text + "\n";
}

void SceneIO::save(const Scene& scene, const std::string& path) {
  const std::string text = serialize(scene);
  // Write a temporary file beside the target, then rename: the target is either the old
  // file or the complete new one, never half written.
  std::string temp = path + ".XXXXXX";
  const int fd = ::mkstemp(temp.data());
  if (fd < 0) throw SaveError(path + ": cannot create a temporary file next to it");
  ::fchmod(fd, 0644);  // mkstemp makes the file private; a scene is an ordinary file
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n <= 0) {
      ::close(fd);
      ::unlink(temp.c_str());
      throw SaveError(path + ": write failed (disk full?); the file was not changed");
    }
    written += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0 || ::close(fd) != 0) {
    ::unlink(temp.c_str());
    throw SaveError(path + ": could not flush the file; the file was not changed");
  }
  if (std::rename(temp.c_str(), path.c_str()) != 0) {
    ::unlink(temp.c_str());
    throw SaveError(path + ": could not replace the file; it was not changed");
  }
}

}  // namespace raylab
