#include "words/UiWords.h"

#include "words/Language.h"

#include "raylab/core/AlgorithmInfo.h"

namespace raylab::app {

Language uiLanguage() {
  return parseLanguage(currentLanguage().toStdString()).value_or(Language::English);
}

QString algorithmLabel(Algorithm algorithm) {
  return QString::fromStdString(algorithmTitle(algorithm, uiLanguage(), AlgorithmName::Long));
}

QString rayKindWord(RayKind kind) {
  return QString::fromStdString(raylab::rayKindWord(kind, uiLanguage()));
}

QString endReasonLabel(EndReason reason) {
  return QString::fromStdString(raylab::endReasonLabel(reason, uiLanguage()));
}

SceneNames shownNames(const Scene& scene) { return sceneNames(scene, uiLanguage()); }

QString traceSummary(const PixelTrace& trace) {
  return QString::fromStdString(raylab::traceSummary(trace, uiLanguage()));
}

}  // namespace raylab::app
