#pragma once

#include "raylab/core/Exception.h"
#include "raylab/core/Scene.h"

#include <string>

namespace raylab {

/**
 * \brief Reads and writes scene files: versioned, human-readable JSON.
 *
 * Format (version 2), all lengths in scene units, angles in degrees, colours linear RGB:
 *
 *     {
 *       "raylab_scene": 2,
 *       "name": "My scene",
 *       "materials": [
 *         {"name": "red", "type": "diffuse", "colour": [0.8, 0.1, 0.1],
 *          "emission": [0, 0, 0], "opacity": 1},
 *         {"name": "chrome", "type": "mirror", "colour": [0.9, 0.9, 0.9],
 *          "reflection_rate": 1, "refraction_rate": 0, "ior": 1.5},
 *         {"name": "glass", "type": "dielectric", "colour": [1, 1, 1], "ior": 1.5},
 *         {"name": "plastic", "type": "glossy", "colour": [0.2, 0.5, 0.2],
 *          "exponent": 200, "specular": 0.3}
 *       ],
 *       "objects": [
 *         {"name": "ball", "material": "red",
 *          "shape": {"type": "sphere", "centre": [0, 1, 0], "radius": 1, "m": 24, "n": 32},
 *          "transform": [ {"scale": [2, 1, 1]}, {"rotate": {"axis": [0, 1, 0], "degrees": 30}},
 *                         {"translate": [0, 0, -2]} ],
 *          "velocity": [0, 0.2, 0]},
 *         {"name": "bunny", "material": "plastic",
 *          "shape": {"type": "mesh", "file": "meshes/bunny.obj"}}
 *       ],
 *       "point_lights": [ {"name": "key", "position": [2, 5, 2], "intensity": [20, 20, 20]} ],
 *       "camera": {"position": [0, 2, 5], "look_at": [0, 1, 0], "up": [0, 1, 0],
 *                  "vertical_fov": 45, "width": 320, "height": 240,
 *                  "aperture": 0, "focus_distance": 0, "near_clip": 0,
 *                  "near_clip_shape": "plane"},
 *       "render": {"algorithm": "path", "spp": 16, "max_depth": 5, "seed": 1,
 *                  "shadow_samples": 4, "glossy_samples": 4, "russian_roulette_depth": 3,
 *                  "next_event_estimation": true, "multiple_importance": true,
 *                  "background": [0, 0, 0]}
 *     }
 *
 * Shapes: sphere (centre, radius, m, n), box (centre, size, optional axes [x, y, z] or
 * a "matrix" mapping [-1, 1]^3), plane (point, normal), quad (corner, u, v), triangle
 * (vertices [p0, p1, p2]), mesh (file: OBJ, PLY, OFF or STL read with MeshIO, the path
 * relative to the scene file's folder; "normals": "file" (default: the file's vertex normals
 * when it has them, else flat), "flat" or "smooth" (computed with "crease_angle", degrees in
 * [0, 180], default 60, in the file's space; read, and checked, whatever "normals" says, but
 * used and written only with "smooth"): see SceneObject::meshNormals). "transform" steps apply in
 * the order listed (first listed first); a step is translate, scale, rotate {axis, degrees} or
 * matrix (4 rows of 4). Materials: type diffuse (default), mirror (the original course program's
 * reflection_rate and refraction_rate, each in [0, 1], summing to at most 1, and ior > 0),
 * dielectric (Fresnel glass of index ior; "fresnel": "exact" or "schlick"), glossy (Phong
 * exponent > 0, specular fraction in [0, 1]), phong and blinn_phong (the classic model of
 * ClassicShading.h: "ambient" RGB >= 0, "diffuse" kd and "specular" ks in [0, 1],
 * "exponent" n, reflection_rate kr (default 0) and refraction_rate kt, ior, "attenuation"
 * [c, l, q] >= 0, not all 0), rough_conductor and rough_dielectric (microfacets:
 * "roughness" alpha in [0.0001, 4], "distribution" "ggx" or "beckmann", "visible_normals"
 * true or false; the dielectric also ior and fresnel). "ior_outside" (> 0, default 1) is
 * the index on a surface's outer side: nested media (water in glass) name both indices
 * at each interface; any material with a non-zero
 * emission is an area light (not allowed on a plane).
 * The camera's "near_clip" d starts camera rays d away from the eye (or the lens point):
 * with "near_clip_shape" "plane" (the default) on the plane d in front of the eye, like
 * OpenGL's near plane; with "sphere" d along each ray, on a sphere around the eye, as
 * smallpt starts its rays (Ray(cam.o + d * 140, d.norm()) with d normalised first).
 * The render block's "ray_offset" (default true) false starts secondary rays on the
 * computed hit point, to show shadow acne. "velocity" is the object's motion over the shutter
 * interval (motion blur). The scene, a material or an object may carry a "display_name":
 * {"zh": "玻璃球"}, the name a Chinese reader sees in the window (object list, inspector),
 * handouts and captions (it must hold a Chinese character; "zh" is its only key); files,
 * lesson scene_changes and scripts keep using "name". Everything but "raylab_scene", "materials"
 * and "objects" is optional and defaults to the values of Material, CameraSpec and RenderSettings;
 * unknown keys are errors (a misspelt key would otherwise be ignored).
 *
 * Versions: version 2 added material types and parameters, point lights, velocity,
 * meshes, the thin-lens camera, the camera's near clip and the render block. Version 1
 * files are still read (they have none of these, so every new field takes its default);
 * files are written as version 2.
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

  /// The file format version this build writes (and the newest it reads).
  static constexpr int kVersion = 2;
  /// The oldest file format version this build reads.
  static constexpr int kFirstVersion = 1;

  /// Reads the scene file at `path`; mesh files are found relative to its folder.
  static Scene load(const std::string& path);
  /// Parses scene text; `origin` names the source in messages, and its folder is where
  /// relative mesh paths are looked for (a bare name: the current directory).
  static Scene parse(const std::string& text, const std::string& origin);
  /// Writes the scene to `path` (temporary file + rename); mesh paths are written
  /// relative to the folder of `path`.
  static void save(const Scene& scene, const std::string& path);
  /// The scene as file text; mesh paths are written relative to `sceneDir` (the folder
  /// the text will be saved in; "" = the current directory).
  static std::string serialize(const Scene& scene, const std::string& sceneDir = "");
};

}  // namespace raylab
