#include "UiWords.h"

#include "Language.h"

#include "raylab/core/AlgorithmInfo.h"
#include "raylab/core/Phrases.h"

#include <QCoreApplication>
#include <QStringList>

#include <algorithm>
#include <array>

namespace raylab::app {

namespace {

/// The texts of this file are translated in the context "UiWords" (lupdate reads the
/// QCoreApplication::translate calls).

/// "2 rays (#5..#6)", "1 ray (#5)", "0 rays".
QString children(const RaySegment& s) {
  if (s.childCount <= 0) return QCoreApplication::translate("UiWords", "0 rays");
  if (s.childCount == 1)
    return QCoreApplication::translate("UiWords", "1 ray (#%1)").arg(s.firstChild);
  return QCoreApplication::translate("UiWords", "%1 rays (#%2..#%3)")
      .arg(s.childCount)
      .arg(s.firstChild)
      .arg(s.firstChild + s.childCount - 1);
}

}  // namespace

Language uiLanguage() {
  return parseLanguage(currentLanguage().toStdString()).value_or(Language::English);
}

QString algorithmLabel(Algorithm algorithm) {
  return QString::fromStdString(algorithmTitle(algorithm, uiLanguage(), AlgorithmName::Long));
}

QString rayKindWord(RayKind kind) {
  return QString::fromStdString(phrase(std::string("ray_kind.") + toString(kind), uiLanguage()));
}

QString endReasonLabel(EndReason reason) {
  switch (reason) {
    case EndReason::Pending:
      return QCoreApplication::translate("UiWords", "pending");
    case EndReason::Escaped:
      return QCoreApplication::translate("UiWords", "escaped");
    case EndReason::HitLight:
      return QCoreApplication::translate("UiWords", "hit a light");
    case EndReason::MaxDepth:
      return QCoreApplication::translate("UiWords", "max depth");
    case EndReason::RussianRoulette:
      return QCoreApplication::translate("UiWords", "Russian roulette");
    case EndReason::Absorbed:
      return QCoreApplication::translate("UiWords", "absorbed");
    case EndReason::Occluded:
      return QCoreApplication::translate("UiWords", "occluded");
    case EndReason::ReachedLight:
      return QCoreApplication::translate("UiWords", "reached its light");
    case EndReason::Spawned:
      return QCoreApplication::translate("UiWords", "spawned children");
    case EndReason::Stopped:
      return QCoreApplication::translate("UiWords", "stopped (budget)");
  }
  return QStringLiteral("?");
}

QString narrateRay(const RayTree& tree, int id, const std::vector<std::string>& objectNames,
                   const std::vector<std::string>& pointLightNames) {
  if (id < 0 || id >= int(tree.segments.size())) return {};
  const RaySegment& s = tree.segments[std::size_t(id)];
  // A shadow ray's light, when its name is known (core describeEnd).
  const QString light = QString::fromStdString(lightNameOf(s, objectNames, pointLightNames));
  const QString ray =
      QCoreApplication::translate("UiWords", "%1 ray #%2").arg(rayKindWord(s.kind)).arg(id);
  const bool named = s.object >= 0 && s.object < int(objectNames.size());
  const QString object =
      named ? QString::fromStdString(objectNames[std::size_t(s.object)]) : QString();
  switch (s.endReason) {
    case EndReason::Pending:
      return QCoreApplication::translate("UiWords", "%1 waits in the queue").arg(ray);
    case EndReason::Escaped:
      return QCoreApplication::translate("UiWords",
                                         "%1 escaped the scene: it gets the background radiance")
          .arg(ray);
    case EndReason::HitLight:
      return named ? QCoreApplication::translate("UiWords",
                                                 "%1 hit the light '%2': the path ends there")
                         .arg(ray, object)
                   : QCoreApplication::translate("UiWords", "%1 hit a light: the path ends there")
                         .arg(ray);
    case EndReason::MaxDepth:
      return named
                 ? QCoreApplication::translate(
                       "UiWords", "%1 hit '%2' and reached the maximum depth: the path ends there")
                       .arg(ray, object)
                 : QCoreApplication::translate("UiWords",
                                               "%1 reached the maximum depth: the path ends there")
                       .arg(ray);
    case EndReason::RussianRoulette:
      return named ? QCoreApplication::translate("UiWords",
                                                 "%1 hit '%2' and was stopped by Russian roulette")
                         .arg(ray, object)
                   : QCoreApplication::translate("UiWords", "%1 was stopped by Russian roulette")
                         .arg(ray);
    case EndReason::Absorbed:
      return named ? QCoreApplication::translate(
                         "UiWords", "%1 hit '%2' and was absorbed: no further ray leaves this hit")
                         .arg(ray, object)
                   : QCoreApplication::translate("UiWords",
                                                 "%1 was absorbed: no further ray leaves this hit")
                         .arg(ray);
    case EndReason::Occluded:
      if (!light.isEmpty())
        return named ? QCoreApplication::translate(
                           "UiWords", "%1 was blocked by '%2' before reaching the light '%3'")
                           .arg(ray, object, light)
                     : QCoreApplication::translate("UiWords",
                                                   "%1 was blocked before reaching the light '%2'")
                           .arg(ray, light);
      return named ? QCoreApplication::translate("UiWords",
                                                 "%1 was blocked by '%2' before reaching its light")
                         .arg(ray, object)
                   : QCoreApplication::translate("UiWords",
                                                 "%1 was blocked before reaching its light")
                         .arg(ray);
    case EndReason::ReachedLight:
      if (!light.isEmpty())
        return QCoreApplication::translate(
                   "UiWords", "%1 reached the light '%2' unblocked and delivers its radiance")
            .arg(ray, light);
      return QCoreApplication::translate("UiWords",
                                         "%1 reached its light unblocked and delivers its radiance")
          .arg(ray);
    case EndReason::Spawned:
      return named ? QCoreApplication::translate("UiWords", "%1 hit '%2' and spawned %3")
                         .arg(ray, object, children(s))
                   : QCoreApplication::translate("UiWords", "%1 spawned %2").arg(ray, children(s));
    case EndReason::Stopped: {
      // Under a budget whole sibling groups are dropped; a cancel may cut one in two.
      const QString what =
          s.childCount == 0 ? QCoreApplication::translate("UiWords", "its children were not traced")
          : s.childCount == 1
              ? QCoreApplication::translate("UiWords", "only 1 child was traced (#%1..#%2)")
                    .arg(s.firstChild)
                    .arg(s.firstChild)
              : QCoreApplication::translate("UiWords", "only %1 children were traced (#%2..#%3)")
                    .arg(s.childCount)
                    .arg(s.firstChild)
                    .arg(s.firstChild + s.childCount - 1);
      return named
                 ? QCoreApplication::translate(
                       "UiWords",
                       "%1 hit '%2'; tracing stopped here (ray budget reached, or cancelled): %3")
                       .arg(ray, object, what)
                 : QCoreApplication::translate(
                       "UiWords", "%1 tracing stopped here (ray budget reached, or cancelled): %2")
                       .arg(ray, what);
    }
  }
  return ray;
}

QString traceSummary(const PixelTrace& trace) {
  const RayTree& tree = trace.tree;
  std::array<int, kRayKindCount> byKind{};
  for (const RaySegment& s : tree.segments) ++byKind[std::size_t(s.kind)];
  QStringList parts;
  for (int k = 0; k < kRayKindCount; ++k)
    if (byKind[std::size_t(k)] > 0)
      parts << QCoreApplication::translate("UiWords", "%1 %2", "kind count")
                   .arg(rayKindWord(RayKind(k)))
                   .arg(byKind[std::size_t(k)]);
  const Vec3 e = tree.estimate();
  const QString estimate = QStringLiteral("(%1, %2, %3)")
                               .arg(QString::number(e.x, 'g', 6), QString::number(e.y, 'g', 6),
                                    QString::number(e.z, 'g', 6));
  const int count = int(tree.segments.size());
  return (count == 1 ? QCoreApplication::translate("UiWords", "1 ray (%1), depth %2, estimate %3")
                           .arg(parts.join(QCoreApplication::translate("UiWords", ", ")))
                           .arg(trace.depth())
                           .arg(estimate)
                     : QCoreApplication::translate("UiWords", "%1 rays (%2), depth %3, estimate %4")
                           .arg(count)
                           .arg(parts.join(QCoreApplication::translate("UiWords", ", ")))
                           .arg(trace.depth())
                           .arg(estimate));
}

std::vector<std::string> objectNamesOf(const Scene& scene) {
  std::vector<std::string> names;
  const bool chinese = currentLanguage() == kChinese;
  for (const SceneObject& object : scene.objects) names.push_back(object.shownName(chinese));
  return names;
}

std::vector<std::string> pointLightNamesOf(const Scene& scene) {
  std::vector<std::string> names;
  for (const PointLight& light : scene.pointLights) names.push_back(light.name);
  return names;
}

QString stepCaption(const PixelTrace& trace, const vis::AnimationSettings& settings, int frame,
                    const std::vector<std::string>& objectNames,
                    const std::vector<std::string>& pointLightNames) {
  const RayTree& tree = trace.tree;
  if (tree.segments.empty()) return QCoreApplication::translate("UiWords", "No ray tree yet.");
  const int perFrame = std::max(1, settings.framesPerStep);
  const int last = vis::frameCount(tree, settings) - 1;
  frame = std::clamp(frame, 0, last);
  const int steps = last / perFrame;
  if (frame == 0)
    return QCoreApplication::translate("UiWords",
                                       "Frame 0: nothing revealed yet. Press Play or Step.");
  const int step = (frame - 1) / perFrame;

  QString text;
  if (settings.order == vis::RevealOrder::Processing) {
    // The engine's own words for the ray (or the first of the rays) leaving now.
    const int perStep = std::max(1, settings.raysPerStep);
    const int first = step * perStep;
    const int end = std::min(int(tree.segments.size()), first + perStep);
    const QString what = narrateRay(tree, first, objectNames, pointLightNames);
    text = end - first == 1
               ? QCoreApplication::translate("UiWords", "Step %1 of %2: %3.")
                     .arg(step + 1)
                     .arg(steps)
                     .arg(what)
               : QCoreApplication::translate("UiWords", "Step %1 of %2: rays #%3..#%4; first: %5.")
                     .arg(step + 1)
                     .arg(steps)
                     .arg(first)
                     .arg(end - 1)
                     .arg(what);
  } else {
    // Every ray of this depth travels at once: count them by kind.
    std::array<int, kRayKindCount> byKind{};
    int count = 0;
    for (const RaySegment& s : tree.segments)
      if (s.depth == step) {
        ++byKind[std::size_t(s.kind)];
        ++count;
      }
    QStringList parts;
    for (int k = 0; k < kRayKindCount; ++k)
      if (byKind[std::size_t(k)] > 0)
        parts << QCoreApplication::translate("UiWords", "%1 %2", "count kind")
                     .arg(byKind[std::size_t(k)])
                     .arg(rayKindWord(RayKind(k)));
    const QString kinds = parts.join(QCoreApplication::translate("UiWords", ", "));
    text = count == 1
               ? QCoreApplication::translate("UiWords", "Depth %1 of %2: 1 ray travels (%3).")
                     .arg(step)
                     .arg(steps - 1)
                     .arg(kinds)
               : QCoreApplication::translate("UiWords", "Depth %1 of %2: %3 rays travel (%4).")
                     .arg(step)
                     .arg(steps - 1)
                     .arg(count)
                     .arg(kinds);
  }
  if (frame == last) text += QCoreApplication::translate("UiWords", " The whole tree is shown.");
  return text;
}

}  // namespace raylab::app
