#pragma once

#include "raylab/core/Language.h"
#include "raylab/core/RayTree.h"
#include "raylab/core/StudentHooks.h"

#include <optional>
#include <string>
#include <vector>

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

/**
 * \brief One verdict per ray of `theirs` against the reference tree, rays matched by id as
 * firstTreeDifference matches them, numbers compared within kTreeDiffTolerance: what the web
 * export's bug-hunt steps colour the faulty engine's tree by.
 *
 * - Verdict::WrongHit: the ray itself goes elsewhere: kind, parent, depth, origin or
 *   direction differ, or both hit but the object, end point or normal differ.
 * - Verdict::MissedHit / Verdict::SpuriousHit: the reference's ray hits and theirs misses,
 *   or the other way round. A ray the reference lacks (theirs has more rays) is a
 *   SpuriousHit too: a ray that should not exist. Rays that theirs lacks have no verdict
 *   (there is no ray of theirs to colour); their parent differs in some field.
 * - Verdict::WrongWeight: the same geometry, but the ray's own energy differs: its weight,
 *   pdf, emitted or end reason; its throughput while its parent's agrees; its radiance while
 *   every child of it agrees. A difference a ray only inherits (the throughput below a wrong
 *   weight, the radiance above it) does not count against it: the verdicts show where the
 *   trees part, not everything downstream of it.
 * - Verdict::Agrees otherwise.
 *
 * Children are expected after their parents in id order (as every recorded tree has them).
 */
std::vector<Verdict> judgeTree(const RayTree& reference, const RayTree& theirs);

/// The sentence naming a difference, in `language` (phrase table "tree_diff.*").
std::string describe(const TreeDifference& difference, Language language);

}  // namespace raylab
