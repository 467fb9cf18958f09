#pragma once

#include "raylab/core/AlgorithmInfo.h"
#include "raylab/core/Language.h"
#include "raylab/core/PixelTrace.h"
#include "raylab/core/RayTree.h"
#include "raylab/core/RayWords.h"
#include "raylab/core/RenderSettings.h"
#include "raylab/core/Scene.h"

#include <QString>

namespace raylab::app {

/// The window's words for core's facts: the phrase table's (Phrases.h, RayWords.h), in the
/// user interface's language, as QStrings. Nothing is composed here: Qt's translation files
/// keep only the window's widget labels.

/// The window's language as core's phrase table names it (currentLanguage()).
Language uiLanguage();

/// "Path tracing (Kajiya 1986)": the algorithm's name and citation.
QString algorithmLabel(Algorithm algorithm);

/// "reflection": the kind of a ray.
QString rayKindWord(RayKind kind);

/// "hit a light": the short label of an end reason.
QString endReasonLabel(EndReason reason);

/// The scene's names as the reader sees them in the window's language (SceneObject::shownName).
SceneNames shownNames(const Scene& scene);

/// "22 rays (camera 1, shadow 9, …), depth 3, estimate (0.1, 0.2, 0.3)" (core traceSummary).
QString traceSummary(const PixelTrace& trace);

}  // namespace raylab::app
