#include "InspectorWords.h"

#include "Language.h"
#include "UiWords.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <QStringList>

#include <utility>
#include <vector>

namespace raylab::app {

namespace {

/// The field names of the inspector (core inspect/InspectorText.cpp), for lupdate.
[[maybe_unused]] constexpr const char* kFields[] = {
    QT_TRANSLATE_NOOP("InspectorWords", "origin"),
    QT_TRANSLATE_NOOP("InspectorWords", "direction"),
    QT_TRANSLATE_NOOP("InspectorWords", "blocked at"),
    QT_TRANSLATE_NOOP("InspectorWords", "hit point"),
    QT_TRANSLATE_NOOP("InspectorWords", "distance"),
    QT_TRANSLATE_NOOP("InspectorWords", "normal"),
    QT_TRANSLATE_NOOP("InspectorWords", "shading"),
    QT_TRANSLATE_NOOP("InspectorWords", "object"),
    QT_TRANSLATE_NOOP("InspectorWords", "material"),
    QT_TRANSLATE_NOOP("InspectorWords", "parameters"),
    QT_TRANSLATE_NOOP("InspectorWords", "light point"),
    QT_TRANSLATE_NOOP("InspectorWords", "light"),
    QT_TRANSLATE_NOOP("InspectorWords", "hit"),
    QT_TRANSLATE_NOOP("InspectorWords", "inside"),
    QT_TRANSLATE_NOOP("InspectorWords", "indices"),
    QT_TRANSLATE_NOOP("InspectorWords", "weight"),
    QT_TRANSLATE_NOOP("InspectorWords", "pdf"),
    QT_TRANSLATE_NOOP("InspectorWords", "throughput"),
    QT_TRANSLATE_NOOP("InspectorWords", "emitted"),
    QT_TRANSLATE_NOOP("InspectorWords", "radiance"),
    QT_TRANSLATE_NOOP("InspectorWords", "energy"),
    QT_TRANSLATE_NOOP("InspectorWords", "ended"),
    QT_TRANSLATE_NOOP("InspectorWords", "exact"),
    QT_TRANSLATE_NOOP("InspectorWords", "double"),
    QT_TRANSLATE_NOOP("InspectorWords", "bound"),
    QT_TRANSLATE_NOOP("InspectorWords", "margin"),
    QT_TRANSLATE_NOOP("InspectorWords", "cosine"),
    QT_TRANSLATE_NOOP("InspectorWords", "verdict"),
    QT_TRANSLATE_NOOP("InspectorWords", "|t error|"),
};

/// Words inside values, longest first so that no shorter one splits a longer one.
constexpr const char* kValueWords[] = {
    QT_TRANSLATE_NOOP("InspectorWords", "differs from double precision:"),
    QT_TRANSLATE_NOOP("InspectorWords", "agrees with double precision"),
    QT_TRANSLATE_NOOP("InspectorWords", "weights kr R, kt (1 - R)"),
    QT_TRANSLATE_NOOP("InspectorWords", "none (deterministic)"),
    QT_TRANSLATE_NOOP("InspectorWords", "(Schlick's Fresnel)"),
    QT_TRANSLATE_NOOP("InspectorWords", "Schlick's Fresnel"),
    QT_TRANSLATE_NOOP("InspectorWords", "rough_dielectric"),
    QT_TRANSLATE_NOOP("InspectorWords", "rough_conductor"),
    QT_TRANSLATE_NOOP("InspectorWords", "refraction rate"),
    QT_TRANSLATE_NOOP("InspectorWords", "reflection rate"),
    QT_TRANSLATE_NOOP("InspectorWords", "specular share"),
    QT_TRANSLATE_NOOP("InspectorWords", "Phong exponent"),
    QT_TRANSLATE_NOOP("InspectorWords", "not traced yet"),
    QT_TRANSLATE_NOOP("InspectorWords", "times the tint"),
    QT_TRANSLATE_NOOP("InspectorWords", "ThroughVertex"),
    QT_TRANSLATE_NOOP("InspectorWords", "interpolated"),
    QT_TRANSLATE_NOOP("InspectorWords", "ThroughEdge"),
    QT_TRANSLATE_NOOP("InspectorWords", "blinn_phong"),
    QT_TRANSLATE_NOOP("InspectorWords", "attenuation"),
    QT_TRANSLATE_NOOP("InspectorWords", "coating ior"),
    QT_TRANSLATE_NOOP("InspectorWords", "dielectric"),
    QT_TRANSLATE_NOOP("InspectorWords", "none (air)"),
    QT_TRANSLATE_NOOP("InspectorWords", "(Fresnel)"),
    QT_TRANSLATE_NOOP("InspectorWords", "shininess"),
    QT_TRANSLATE_NOOP("InspectorWords", ", a light"),
    QT_TRANSLATE_NOOP("InspectorWords", "roughness"),
    QT_TRANSLATE_NOOP("InspectorWords", "incidence"),
    QT_TRANSLATE_NOOP("InspectorWords", "(robust)"),
    QT_TRANSLATE_NOOP("InspectorWords", "entering"),
    QT_TRANSLATE_NOOP("InspectorWords", "priority"),
    QT_TRANSLATE_NOOP("InspectorWords", "diffuse"),
    QT_TRANSLATE_NOOP("InspectorWords", "Tangent"),
    QT_TRANSLATE_NOOP("InspectorWords", "ambient"),
    QT_TRANSLATE_NOOP("InspectorWords", "nothing"),
    QT_TRANSLATE_NOOP("InspectorWords", "leaving"),
    QT_TRANSLATE_NOOP("InspectorWords", "plastic"),
    QT_TRANSLATE_NOOP("InspectorWords", "degrees"),
    QT_TRANSLATE_NOOP("InspectorWords", "Fresnel"),
    QT_TRANSLATE_NOOP("InspectorWords", "per sr"),
    QT_TRANSLATE_NOOP("InspectorWords", "albedo"),
    QT_TRANSLATE_NOOP("InspectorWords", "mirror"),
    QT_TRANSLATE_NOOP("InspectorWords", "glossy"),
    QT_TRANSLATE_NOOP("InspectorWords", "colour"),
    QT_TRANSLATE_NOOP("InspectorWords", "emits"),
    QT_TRANSLATE_NOOP("InspectorWords", "phong"),
    QT_TRANSLATE_NOOP("InspectorWords", "tint"),
    QT_TRANSLATE_NOOP("InspectorWords", "Miss"),
    QT_TRANSLATE_NOOP("InspectorWords", "base"),
    QT_TRANSLATE_NOOP("InspectorWords", "Hit"),
};

QString word(const char* text) { return QCoreApplication::translate("InspectorWords", text); }

/// `value` with its words translated, leaving quoted names alone.
QString translateValue(const QString& value) {
  // Split off quoted names ('red sphere'), translate the rest.
  static const QRegularExpression quoted(QStringLiteral("'[^']*'"));
  QString out;
  int last = 0;
  const auto translate = [](QString text) {
    for (const char* w : kValueWords) text.replace(QString::fromLatin1(w), word(w));
    return text;
  };
  auto it = quoted.globalMatch(value);
  while (it.hasNext()) {
    const auto m = it.next();
    out += translate(value.mid(last, m.capturedStart() - last));
    out += QStringLiteral("“") + m.captured().mid(1, m.capturedLength() - 2) + QStringLiteral("”");
    last = m.capturedEnd();
  }
  return out + translate(value.mid(last));
}

/// One of the exact oracle's notes (core inspect/OracleCheck.cpp), in the window's
/// language; a note it does not know stays as it is.
QString oracleNote(const QString& note) {
  struct Pattern {
    const char* regex;
    const char* text;  ///< %1, %2: the captures, in order.
  };
  static const Pattern patterns[] = {
      {"^The exact oracle says the ray hits '(.*)' but double precision misses it\\.$",
       QT_TRANSLATE_NOOP(
           "InspectorWords",
           "The exact oracle says the ray hits '%1' but double precision misses it.")},
      {"^The exact oracle says the ray misses '(.*)' but double precision hits it\\.$",
       QT_TRANSLATE_NOOP(
           "InspectorWords",
           "The exact oracle says the ray misses '%1' but double precision hits it.")},
      {"^Exactly tangent: the ray touches '(.*)' without crossing it; doubles cannot decide "
       "this reliably\\.$",
       QT_TRANSLATE_NOOP("InspectorWords",
                         "Exactly tangent: the ray touches '%1' without crossing it; doubles "
                         "cannot decide this reliably.")},
      {"^The exact hit lies on an edge: a neighbouring face could be hit instead in doubles\\.$",
       QT_TRANSLATE_NOOP("InspectorWords",
                         "The exact hit lies on an edge: a neighbouring face could be hit "
                         "instead in doubles.")},
      {"^The exact hit lies on a vertex: a neighbouring face could be hit instead in "
       "doubles\\.$",
       QT_TRANSLATE_NOOP("InspectorWords",
                         "The exact hit lies on a vertex: a neighbouring face could be hit "
                         "instead in doubles.")},
      {"^The double t is off by (\\S+), more than the usual bound (\\S+) \\(a grazing ray or "
       "an ill-conditioned transform\\)\\.$",
       QT_TRANSLATE_NOOP("InspectorWords",
                         "The double t is off by %1, more than the usual bound %2 (a grazing "
                         "ray or an ill-conditioned transform).")},
      {"^The exact oracle hits primitive (\\d+), double precision primitive (\\d+)\\.$",
       QT_TRANSLATE_NOOP("InspectorWords",
                         "The exact oracle hits primitive %1, double precision primitive %2.")},
      {"^The recorded hit is (\\S+) along the ray, the object's nearest exact hit (\\S+)\\.$",
       QT_TRANSLATE_NOOP("InspectorWords",
                         "The recorded hit is %1 along the ray, the object's nearest exact hit "
                         "%2.")},
  };
  static const std::vector<QRegularExpression> compiled = [] {
    std::vector<QRegularExpression> out;
    for (const Pattern& p : patterns) out.emplace_back(QString::fromUtf8(p.regex));
    return out;
  }();
  for (std::size_t i = 0; i < compiled.size(); ++i) {
    const Pattern& p = patterns[i];
    const QRegularExpressionMatch m = compiled[i].match(note);
    if (!m.hasMatch()) continue;
    QString said = QCoreApplication::translate("InspectorWords", p.text);
    for (int k = 1; k <= m.lastCapturedIndex(); ++k) said = said.arg(m.captured(k));
    return said;
  }
  return note;
}

}  // namespace

QString inspectorText(const std::string& coreText, const RayTree& tree, int id,
                      const std::vector<std::string>& objectNames,
                      const std::vector<std::string>& pointLightNames) {
  const QString text = QString::fromStdString(coreText);
  if (currentLanguage() != kChinese || id < 0 || id >= int(tree.segments.size())) return text;
  const RaySegment& s = tree.segments[std::size_t(id)];
  QStringList out;
  static const QRegularExpression oracle(QStringLiteral("^Exact oracle \\(CGAL\\) on '(.*)':$"));
  for (const QString& line : text.split(QLatin1Char('\n'))) {
    if (line.startsWith(QStringLiteral("Ray #"))) {
      // "Ray #3: reflection ray, depth 2, child of #1, time 0.5"
      QString head = QCoreApplication::translate("InspectorWords", "Ray #%1: %2 ray, depth %3")
                         .arg(id)
                         .arg(rayKindWord(s.kind))
                         .arg(s.depth);
      if (s.parent >= 0)
        head += QCoreApplication::translate("InspectorWords", ", child of #%1").arg(s.parent);
      if (s.time != 0.0)
        head += QCoreApplication::translate("InspectorWords", ", time %1")
                    .arg(QString::number(s.time, 'g', 3));
      out << head;
    } else if (const auto m = oracle.match(line); m.hasMatch()) {
      out << QCoreApplication::translate("InspectorWords", "Exact oracle (CGAL) on '%1':")
                 .arg(m.captured(1));
    } else if (line == QStringLiteral("Exact oracle: not computed")) {
      out << QCoreApplication::translate("InspectorWords", "Exact oracle: not computed");
    } else if (line == QStringLiteral("Exact oracle: no hit to check")) {
      out << QCoreApplication::translate("InspectorWords", "Exact oracle: no hit to check");
    } else if (line.startsWith(QStringLiteral("    ")) &&
               !line.startsWith(QStringLiteral("    t "))) {
      out << QStringLiteral("    ") + oracleNote(line.mid(4));  // the oracle's notes
    } else if (line.size() > 14 && line.startsWith(QStringLiteral("  ")) && line[2] != ' ') {
      // "  %-12s" then the value (core inspect::line).
      const QString label = line.mid(2, 12).trimmed();
      const QString value = line.mid(14);
      const QString name = word(label.toUtf8().constData());
      const QString said = label == QStringLiteral("ended")
                               ? narrateRay(tree, id, objectNames, pointLightNames)
                               : translateValue(value);
      out << QStringLiteral("  %1  %2").arg(name, said);
    } else {
      out << line;
    }
  }
  return out.join(QLatin1Char('\n'));
}

}  // namespace raylab::app
