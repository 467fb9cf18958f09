#pragma once

#include "raylab/core/Exception.h"
#include "raylab/core/Scene.h"

#include <string>

namespace raylab {

/**
 * \brief Reads and writes scene files: versioned, human-readable JSON.
 *
 * Format (version 1), all lengths in scene units, angles in degrees:
 *
 *     {
 *       "raylab_scene": 1,
 *       "name": "My scene",
 *       "materials": [ {"name": "red", "colour": [0.8, 0.1, 0.1],
 *                       "emission": [0, 0, 0], "opacity": 1} ],
 *       "objects": [
 *         {"name": "ball", "material": "red",
 *          "shape": {"type": "sphere", "centre": [0, 1, 0], "radius": 1, "m": 24, "n": 32},
 *          "transform": [ {"scale": [2, 1, 1]}, {"rotate": {"axis": [0, 1, 0], "degrees": 30}},
 *                         {"translate": [0, 0, -2]} ]}
 *       ],
 *       "camera": {"position": [0, 2, 5], "look_at": [0, 1, 0], "up": [0, 1, 0],
 *                  "vertical_fov": 45, "width": 320, "height": 240}
 *     }
 *
 * Shapes: sphere (centre, radius, m, n), box (centre, size, optional axes [x, y, z] or
 * a "matrix" mapping [-1, 1]^3), plane (point, normal), quad (corner, u, v), triangle
 * (vertices [p0, p1, p2]). "transform" steps apply in the order listed (first listed
 * first); a step is translate, scale, rotate {axis, degrees} or matrix (4 rows of 4).
 *
 * Every error names the file and the place: line and column for JSON syntax, the JSON
 * path (e.g. /objects/2/shape/radius) for content. A failed load throws and returns
 * nothing, so the caller's scene is untouched; a save writes a temporary file next to
 * the target and renames it over the target only when complete.
 */
class SceneIO {
 public:
  /// A scene file that cannot be read: syntax, content or version error.
  class LoadError : public Exception {
   public:
    using Exception::Exception;
  };
  /// A scene that could not be written; the target file is unchanged.
  class SaveError : public Exception {
   public:
    using Exception::Exception;
  };

  /// The file format version this build reads and writes.
  static constexpr int kVersion = 1;

  static Scene load(const std::string& path);
  /// Parses scene text; `origin` names the source in messages.
  static Scene parse(const std::string& text, const std::string& origin);
  static void save(const Scene& scene, const std::string& path);
  static std::string serialize(const Scene& scene);
};

}  // namespace raylab
