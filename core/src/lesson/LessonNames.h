#pragma once

#include "raylab/core/AlgorithmInfo.h"
#include "raylab/core/Lesson.h"

#include <array>
#include <iterator>
#include <type_traits>
#include <utility>

#include <cstddef>
#include <optional>
#include <string>

/// \file LessonNames.h
/// The words of a lesson file for views, colourings, samplers, quantities, algorithms, ray
/// kinds and end reasons, and the table look-ups the reader and `toString` share. Private
/// to core's lesson code.

namespace raylab::lessonfile {

/// A name in a lesson file and the value it stands for.
template <class E>
struct Named {
  const char* name;
  E value;
};

inline const Named<LessonView> kViews[] = {
    {"scene", LessonView::Scene},         {"image", LessonView::Image},
    {"compare", LessonView::Compare},     {"plot", LessonView::Plot},
    {"inspector", LessonView::Inspector}, {"samples", LessonView::Samples}};
inline const Named<LessonColouring> kColourings[] = {{"energy", LessonColouring::Energy},
                                                     {"kind", LessonColouring::Kind},
                                                     {"depth", LessonColouring::Depth}};
inline const Named<LessonCameraView> kCameraViews[] = {{"default", LessonCameraView::Default},
                                                       {"camera", LessonCameraView::Camera},
                                                       {"close_up", LessonCameraView::CloseUp}};
inline const Named<LessonMeasure> kMeasures[] = {{"samples", LessonMeasure::Samples},
                                                 {"time", LessonMeasure::Time}};
inline const Named<LessonSamples::Sampler> kSamplers[] = {
    {"cosine", LessonSamples::Sampler::Cosine},
    {"uniform", LessonSamples::Sampler::Uniform},
    {"sphere", LessonSamples::Sampler::Sphere},
    {"phong", LessonSamples::Sampler::Phong}};
inline const Named<LessonCheck::Quantity> kQuantities[] = {
    {"tree_rays", LessonCheck::Quantity::TreeRays},
    {"tree_depth", LessonCheck::Quantity::TreeDepth},
    {"estimate_luminance", LessonCheck::Quantity::EstimateLuminance},
    {"pixel_luminance", LessonCheck::Quantity::PixelLuminance},
    {"ray_length", LessonCheck::Quantity::RayLength},
    {"camera_rays", LessonCheck::Quantity::CameraRays},
    {"bvh_nodes", LessonCheck::Quantity::BvhNodes},
    {"bvh_boxes_entered", LessonCheck::Quantity::BvhBoxesEntered},
    {"bvh_triangle_tests", LessonCheck::Quantity::BvhTriangleTests},
    {"ray_target", LessonCheck::Quantity::RayTarget}};
/// The algorithms' words, from the one algorithm table (AlgorithmInfo.h).
inline const std::array<Named<Algorithm>, kAllAlgorithms.size()> kAlgorithms = [] {
  std::array<Named<Algorithm>, kAllAlgorithms.size()> table{};
  for (std::size_t i = 0; i < table.size(); ++i)
    table[i] = {algorithmInfo(kAllAlgorithms[i]).word, kAllAlgorithms[i]};
  return table;
}();
inline const Named<RayKind> kKinds[] = {
    {"camera", RayKind::Camera},         {"reflection", RayKind::Reflection},
    {"refraction", RayKind::Refraction}, {"diffuse", RayKind::Diffuse},
    {"glossy", RayKind::Glossy},         {"shadow", RayKind::Shadow}};
inline const Named<EndReason> kEnds[] = {{"escaped", EndReason::Escaped},
                                         {"hit_light", EndReason::HitLight},
                                         {"max_depth", EndReason::MaxDepth},
                                         {"russian_roulette", EndReason::RussianRoulette},
                                         {"absorbed", EndReason::Absorbed},
                                         {"occluded", EndReason::Occluded},
                                         {"reached_light", EndReason::ReachedLight},
                                         {"spawned", EndReason::Spawned}};

/// The value type of a table of Named values (a C array or a std::array).
template <class Table>
using NamedValue = std::decay_t<decltype(std::begin(std::declval<const Table&>())->value)>;

template <class Table>
std::optional<NamedValue<Table>> lookup(const Table& table, const std::string& name) {
  for (const auto& entry : table)
    if (name == entry.name) return entry.value;
  return std::nullopt;
}

template <class Table>
const char* nameOf(const Table& table, NamedValue<Table> value) {
  for (const auto& entry : table)
    if (entry.value == value) return entry.name;
  return "unknown";
}

/// "a, b or c": the names of a table, for messages.
template <class Table>
std::string namesOf(const Table& table) {
  const std::size_t count = std::size(table);
  std::string list;
  for (std::size_t i = 0; i < count; ++i)
    list += std::string(i == 0 ? "" : i + 1 == count ? " or " : ", ") + table[i].name;
  return list;
}

/// True when UTF-8 `text` holds a CJK unified ideograph (U+4E00..U+9FFF).
inline bool hasChinese(const std::string& text) {
  for (std::size_t i = 0; i + 2 < text.size(); ++i) {
    const auto b0 = static_cast<unsigned char>(text[i]);
    if ((b0 & 0xF0) != 0xE0) continue;
    const unsigned cp = ((b0 & 0x0Fu) << 12) |
                        ((static_cast<unsigned char>(text[i + 1]) & 0x3Fu) << 6) |
                        (static_cast<unsigned char>(text[i + 2]) & 0x3Fu);
    if (cp >= 0x4E00 && cp <= 0x9FFF) return true;
  }
  return false;
}

}  // namespace raylab::lessonfile
