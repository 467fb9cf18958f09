#pragma once

#include "raylab/core/AlgorithmInfo.h"
#include "raylab/core/Language.h"
#include "raylab/core/PixelTrace.h"
#include "raylab/core/RayTree.h"
#include "raylab/core/RenderSettings.h"
#include "raylab/core/Scene.h"
#include "raylab/vis/BounceAnimation.h"

#include <QString>

#include <string>
#include <vector>

namespace raylab::app {

/// The words of core's concepts as the window shows them, in the user interface's
/// language. Core keeps its English words for files, the command line and the JSON dumps;
/// in English these functions say exactly what core says (a test compares them).

/// The window's language as core's phrase table names it (currentLanguage()).
Language uiLanguage();

/// "Path tracing (Kajiya 1986)": the algorithm's name and citation.
QString algorithmLabel(Algorithm algorithm);

/// "reflection": the kind of a ray (core toString(RayKind)).
QString rayKindWord(RayKind kind);

/// "hit a light": the short label of an end reason (core words(reason).label).
QString endReasonLabel(EndReason reason);

/**
 * \brief What ray `id` of `tree` did, in one sentence: "reflection ray #3 hit 'glass ball'
 * and spawned 2 rays (#5..#6)" — the stepper's narration (core PixelTrace::stepTexts),
 * composed from the recorded segment so that it can be translated.
 */
QString narrateRay(const RayTree& tree, int id, const std::vector<std::string>& objectNames,
                   const std::vector<std::string>& pointLightNames = {});

/// "22 rays (camera 1, shadow 9, …), depth 3, estimate (0.1, 0.2, 0.3)": a trace's figures
/// (core PixelTrace::summary, translated).
QString traceSummary(const PixelTrace& trace);

/// The animation's caption at `frame` (vis::stepCaption, translated): which step or depth
/// is travelling, in the engine's words.
QString stepCaption(const PixelTrace& trace, const vis::AnimationSettings& settings, int frame,
                    const std::vector<std::string>& objectNames,
                    const std::vector<std::string>& pointLightNames = {});
/// The names of the scene's objects and of its point lights, as narrateRay takes them: the
/// objects' Chinese display names while the window speaks Chinese (SceneObject::shownName).
std::vector<std::string> objectNamesOf(const Scene& scene);
std::vector<std::string> pointLightNamesOf(const Scene& scene);

}  // namespace raylab::app
