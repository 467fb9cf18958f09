#pragma once

#include "raylab/core/Language.h"
#include "raylab/core/PixelTrace.h"
#include "raylab/core/RayTree.h"
#include "raylab/core/Tracer.h"

#include <array>
#include <string>
#include <vector>

namespace raylab {

struct Scene;

/**
 * \brief The words of traced rays, from the phrase table (Phrases.h): what every front end
 * (the command line, vis captions, the window, handouts, Python) says of a ray, a step of
 * the engine or a whole trace, in English or Chinese. Core's engine records facts only
 * (StepEvent, RaySegment); these functions turn them into sentences.
 */

/// The names a reader sees of what a ray can meet: objects indexed like Scene::objects,
/// point lights like Scene::pointLights.
struct SceneNames {
  std::vector<std::string> objects;
  std::vector<std::string> pointLights;
};
/// The scene's names in `language` (an object's Chinese display name, SceneObject::shownName,
/// in Chinese).
SceneNames sceneNames(const Scene& scene, Language language);

/// "reflection", "反射": the kind of a ray.
std::string rayKindWord(RayKind kind, Language language);
/// "hit a light", "击中光源": the short label of an end reason (lists, legends).
std::string endReasonLabel(EndReason reason, Language language);

/// The facts of recorded ray `s`, as the step that processed it would have reported them
/// (without the children a stopped step wanted, which the tree does not keep).
StepEvent stepEventOf(const RaySegment& s);

/// How a step ended, as a clause after its subject: "hit 'glass ball' and spawned 2 rays
/// (#5..#6)", naming the object hit or blocking, a shadow ray's light and the children.
std::string endClause(const StepEvent& event, const SceneNames& names, Language language);
/// What one step of the engine did, in one sentence: "reflection ray #3 hit 'glass ball'
/// and spawned 2 rays (#5..#6)", "反射光线 #3 击中“玻璃球”，产生 2 条光线（#5..#6）".
std::string narrateStep(const StepEvent& event, const SceneNames& names, Language language);
/// The same for ray `id` of `tree` (stepEventOf); "" when the tree has no such ray.
std::string narrateRay(const RayTree& tree, int id, const SceneNames& names, Language language);

/// "22 rays (camera 1, shadow 9, ...), depth 3, estimate (0.1, 0.2, 0.3)": a trace's figures.
std::string traceSummary(const PixelTrace& trace, Language language);

/// "camera 1, shadow 9" (`countFirst` false) or "1 camera, 9 shadow" (true, the animation's
/// depth captions): the rays of `counts` by kind, the kinds with none left out.
std::string kindCounts(const std::array<int, kRayKindCount>& counts, Language language,
                       bool countFirst);

}  // namespace raylab
