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

/// Why a tree stopped early: "ray budget reached: the tree stops at 40 rays (...)",
/// "cancelled after 12 rays: the tree is cut short"; "" when it did not stop early.
std::string stopWords(const TreeStop& stop, Language language);
/// Why a grid or a bundle stopped early: "cancelled after 3 of 16 pixels; the last tree is
/// cut short"; "" when it did not.
std::string stopWords(const GridStop& stop, Language language);

/// "(0.1, 0.2, 0.3)": a vector as the trace's words print it (6 significant digits).
std::string vectorWords(const Vec3& v);
/// The trace's heading, then its figures (traceSummary) on the next line: "Whitted ray
/// tracing: pixel (3, 4), sample 0", or "...: a chosen ray from (...) along (...)".
std::string traceHeading(const PixelTrace& trace, Language language);
/// "Whitted ray tracing: Simulate 4 x 3, 12 pixels, 80 rays": a grid of pixels traced.
std::string gridHeading(Algorithm algorithm, int across, int down, const GridTrace& grid,
                        Language language);
/// "...: pixel (3, 4), samples 0 to 15 drawn together, 90 rays": a pixel's bundle.
std::string bundleHeading(Algorithm algorithm, int x, int y, int first, const GridTrace& bundle,
                          Language language);

/// "camera 1, shadow 9" (`countFirst` false) or "1 camera, 9 shadow" (true, the animation's
/// depth captions): the rays of `counts` by kind, the kinds with none left out.
std::string kindCounts(const std::array<int, kRayKindCount>& counts, Language language,
                       bool countFirst);

}  // namespace raylab
