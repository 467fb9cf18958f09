#pragma once

#include "raylab/core/Language.h"
#include "raylab/core/RayTree.h"

#include <optional>
#include <string>

namespace raylab {

/**
 * \brief The first ray where two recorded trees of the same pixel sample differ: what
 * `raylab diff` reports of a tree a student's own tracer wrote (any language, the ray tree
 * JSON of doc/ray-tree-json.md) against the engine's.
 *
 * Rays are compared in id order (the writer's processing order), field by field in the
 * order kind, parent, depth, origin, direction, hit, object, end_point, normal, end_reason,
 * weight, pdf, throughput, emitted, radiance; then the number of rays. Numbers agree when
 * |a - b| <= kTreeDiffTolerance * max(1, |a|, |b|) (a relative tolerance for large values,
 * an absolute one near zero).
 */
constexpr double kTreeDiffTolerance = 1e-6;

/// One difference: the ray (id in both trees), the JSON field, both values as text.
struct TreeDifference {
  int ray = -1;        ///< Id of the ray; for a missing ray, the first id one tree lacks.
  std::string field;   ///< JSON name of the field ("end_point"), or "rays" for the count.
  std::string ours;    ///< The engine's value ("[0, 0, -2]"; "none" for a missing ray).
  std::string theirs;  ///< The student's value.
};

/// The first difference between the engine's tree `ours` and `theirs`, or nothing when they
/// agree within kTreeDiffTolerance.
std::optional<TreeDifference> firstTreeDifference(const RayTree& ours, const RayTree& theirs);

/// The sentence naming a difference, in `language` (phrase table "tree_diff.*").
std::string describe(const TreeDifference& difference, Language language);

}  // namespace raylab
