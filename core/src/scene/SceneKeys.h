#pragma once

#include "raylab/core/Material.h"

#include <array>
#include <string>

namespace raylab {

/**
 * \brief The keys of each kind of JSON object in a scene file (see SceneIO.h), one list per
 * kind, in the order the writer emits them.
 *
 * The reader rejects any key missing from its object's list (SceneReader.cpp, `onlyKeys`),
 * and the writer can only add keys of the list, in list order (ObjectWriter.h); so a file RayLab
 * writes always passes its own key check. Adding a field means adding its key here, where the
 * reader and the writer both see it.
 */

/// The document itself.
inline constexpr std::array kSceneKeys = {"raylab_scene", "name",    "display_name",
                                          "materials",    "objects", "point_lights",
                                          "camera",       "render"};
/// One entry of "materials".
inline constexpr std::array kMaterialKeys = {"name",
                                             "display_name",
                                             "type",
                                             "colour",
                                             "texture",
                                             "emission",
                                             "reflection_rate",
                                             "refraction_rate",
                                             "ior",
                                             "exponent",
                                             "specular",
                                             "opacity",
                                             "ambient",
                                             "diffuse",
                                             "attenuation",
                                             "fresnel",
                                             "distribution",
                                             "roughness",
                                             "visible_normals",
                                             "ior_outside",
                                             "priority"};
/// A material's "texture" (Texture.h).
inline constexpr std::array kTextureKeys = {"type", "scale", "colour2"};
/// Sets a material's "fresnel" from its word: none, exact or schlick weighing the rates of a
/// mirror, phong or blinn_phong (Material::rateFresnel), exact or schlick a dielectric's
/// reflectance (Material::fresnel). Returns "" or, for a word its type does not take, the
/// problem (Scene.cpp).
std::string setFresnel(Material& m, const std::string& word);
/// One entry of "objects".
inline constexpr std::array kObjectKeys = {"name",  "display_name", "material",
                                           "shape", "transform",    "velocity"};
/// A "display_name": the name in other languages than the file's English one.
inline constexpr std::array kDisplayNameKeys = {"zh"};
/// One step of an object's "transform" (a step has exactly one of these keys).
inline constexpr std::array kTransformStepKeys = {"translate", "scale", "rotate", "matrix"};
/// One entry of "point_lights".
inline constexpr std::array kPointLightKeys = {"name", "position", "intensity"};
/// The "camera" object.
inline constexpr std::array kCameraKeys = {
    "position", "look_at",        "up",        "vertical_fov",   "width", "height",
    "aperture", "focus_distance", "near_clip", "near_clip_shape"};
/// The "render" object.
inline constexpr std::array kRenderKeys = {"algorithm",
                                           "spp",
                                           "max_depth",
                                           "seed",
                                           "shadow_samples",
                                           "glossy_samples",
                                           "russian_roulette_depth",
                                           "next_event_estimation",
                                           "multiple_importance",
                                           "background",
                                           "ray_offset",
                                           "acceleration",
                                           "bvh_split"};

// An object's "shape": each shape's keys sit beside the shape, in its ShapeFormat
// (ShapeFormat.h, core/src/shapes/<Shape>.cpp).

}  // namespace raylab
