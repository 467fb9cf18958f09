// The ray inspector's words (InspectorWords.h): facts of RayInspector into rows and text.
#include "raylab/core/InspectorWords.h"

#include "inspect/InspectorFormat.h"
#include "raylab/core/Phrases.h"
#include "raylab/core/RayWords.h"

#include <cstdio>

namespace raylab {

using inspect::number;
using inspect::vec;

namespace {

/// Rows in one language: `add("origin", value)` appends the field's words and the value.
struct Rows {
  Language language;
  std::vector<InspectorRow> rows;
  void add(const std::string& field, std::string value) {
    rows.push_back({phrase("inspector.field." + field, language), std::move(value)});
  }
  std::string say(std::string_view key, const PhraseArguments& arguments = {}) const {
    return phrase(key, language, arguments);
  }
};

/// ", weights kr R, kt (1 - R) (Schlick's Fresnel)" when the rates are Fresnel-weighted.
std::string rateWeights(const Material& m, Language language) {
  if (m.rateFresnel == FresnelModel::None) return "";
  return phrase(m.rateFresnel == FresnelModel::Schlick ? "parameter.weights.schlick"
                                                       : "parameter.weights.exact",
                language);
}

/// The parameters of `m`, as (phrase key of the name, value) pairs in the model's order.
std::vector<std::pair<std::string, std::string>> parameterList(const Material& m) {
  switch (m.type) {
    case MaterialType::Diffuse:
      return {{"albedo", vec(m.colour)}};
    case MaterialType::Mirror:
      return {{"tint", vec(m.colour)},
              {"reflection_rate", number(m.reflectionRate)},
              {"refraction_rate", number(m.refractionRate)},
              {"ior", number(m.ior)}};
    case MaterialType::Dielectric:
      return {{"tint", vec(m.colour)}, {"ior", number(m.ior)}};
    case MaterialType::Glossy:
      return {{"colour", vec(m.colour)},
              {"phong_exponent", number(m.exponent)},
              {"specular_share", number(m.specular)}};
    case MaterialType::Phong:
    case MaterialType::BlinnPhong:
      return {{"colour", vec(m.colour)},         {"ambient", vec(m.ambient)},
              {"kd", number(m.diffuse)},         {"ks", number(m.specular)},
              {"shininess", number(m.exponent)}, {"kr", number(m.reflectionRate)},
              {"kt", number(m.refractionRate)},  {"attenuation", vec(m.attenuation)}};
    case MaterialType::RoughConductor:
      return {{"f0", vec(m.colour)}, {"roughness", number(m.roughness)}};
    case MaterialType::RoughDielectric:
      return {{"tint", vec(m.colour)}, {"ior", number(m.ior)}, {"roughness", number(m.roughness)}};
    case MaterialType::Plastic:
      return {{"base", vec(m.colour)},
              {"coating_ior", number(m.ior)},
              {"roughness", number(m.roughness)}};
  }
  return {};
}

/// What follows the list: the Fresnel model of a dielectric or a microfacet model, the
/// rates' weights of a mirror or a classic material.
std::string parameterSuffix(const Material& m, Language language) {
  switch (m.type) {
    case MaterialType::Mirror:
    case MaterialType::Phong:
    case MaterialType::BlinnPhong:
      return rateWeights(m, language);
    case MaterialType::Dielectric:
      return phrase(m.fresnel == FresnelModel::Schlick ? "parameter.fresnel.schlick"
                                                       : "parameter.fresnel.exact",
                    language);
    case MaterialType::RoughDielectric:
    case MaterialType::Plastic:
      return phrase("parameter.fresnel.named", language, {{"model", toString(m.fresnel)}});
    default:
      return "";
  }
}

/// "kr R = 0.5 x 0.04 = 0.02 (Schlick's Fresnel, incidence 0 degrees)".
std::string rateWeightWords(const RateWeight& w, Language language) {
  return phrase(w.reflected ? "inspector.weight.reflected" : "inspector.weight.refracted", language,
                {{"rate", number(w.rate, 4)},
                 {"share", number(w.share, 4)},
                 {"product", number(w.rate * w.share, 4)},
                 {"tint", w.timesTint ? phrase("inspector.weight.tint", language) : ""},
                 {"fresnel", phrase(w.model != FresnelModel::Exact ? "inspector.weight.schlick"
                                                                   : "inspector.weight.exact",
                                    language)},
                 {"degrees", number(w.incidence, 4)}});
}

/// The volumes a ray is inside: "'water' (n 1.33, priority 1): n = 1.33", or "none (air)".
std::string mediaWords(const RayInspection& r, Language language) {
  if (r.media.empty()) return phrase("inspector.inside.none", language);
  std::string volumes;
  for (const MediumEntry& m : r.media) {
    if (!volumes.empty()) volumes += phrase("inspector.inside.separator", language);
    volumes += phrase(
        "inspector.inside.volume", language,
        {{"name", m.name}, {"n", number(m.ior, 4)}, {"priority", std::to_string(m.priority)}});
  }
  return phrase("inspector.inside.volumes", language,
                {{"volumes", volumes}, {"n", number(r.mediumIor, 4)}});
}

/// The names the inspection knows (the object hit, the light aimed at), indexed as the
/// scene's, for the ending's words.
SceneNames namesOf(const RayInspection& r) {
  SceneNames names;
  const auto put = [](std::vector<std::string>& list, int index, const std::string& name) {
    if (index < 0 || name.empty()) return;
    if (list.size() <= std::size_t(index)) list.resize(std::size_t(index) + 1);
    list[std::size_t(index)] = name;
  };
  put(names.objects, r.segment.object, r.objectName);
  put(names.objects, r.segment.lightObject, r.lightName);
  put(names.pointLights, r.segment.pointLight, r.lightName);
  return names;
}

/// Where the ray ended: the hit, its object and material; or the light it reached.
void addEnd(Rows& out, const RayInspection& r) {
  const RaySegment& s = r.segment;
  if (s.hit) {
    out.add(s.kind == RayKind::Shadow ? "blocked_at" : "hit_point", vec(s.endPoint));
    out.add("distance", number(r.distance));
    out.add("normal", vec(s.normal));
    // A smooth surface shades with another normal, interpolated from its vertices'.
    if (!isZero(s.shadingNormal) && s.shadingNormal != s.normal)
      out.add("shading", out.say("inspector.shading", {{"normal", vec(s.shadingNormal)}}));
    out.add("object", out.say("inspector.quoted", {{"name", r.objectName}}));
    if (r.material) {
      out.add(
          "material",
          out.say(r.material->emitter ? "inspector.material.light" : "inspector.material",
                  {{"name", r.material->name},
                   {"type", out.say(std::string("material_type.") + toString(r.material->type))}}));
      std::string parameters = materialParameters(r.material->material, out.language);
      if (r.material->texel)
        parameters += out.say("parameter.texel", {{"colour", vec(*r.material->texel)}});
      out.add("parameters", parameters);
    }
    if (s.kind == RayKind::Shadow) out.add("light_point", vec(r.lightPoint));
  } else if (s.kind == RayKind::Shadow && s.endReason == EndReason::ReachedLight) {
    out.add("light_point", vec(s.endPoint));
    out.add("distance", number(r.distance));
  } else {
    out.add("hit", out.say(s.endReason == EndReason::Pending ? "inspector.hit.not_traced"
                                                             : "inspector.hit.nothing"));
  }
}

/// One line of text of `row` ("  %-12s" and the value in English).
std::string line(const InspectorRow& row, Language language) {
  if (row.field.empty()) return phrase("inspector.note", language, {{"note", row.value}}) + "\n";
  return phrase(row.sub ? "inspector.line.sub" : "inspector.line", language,
                {{"field", row.field}, {"value", row.value}}) +
         "\n";
}

/// The oracle's note in words.
std::string noteWords(const OracleNote& note, const std::string& name, Language language) {
  using Kind = OracleNote::Kind;
  switch (note.kind) {
    case Kind::HitsButDoubleMisses:
      return phrase("oracle.note.hits_but_double_misses", language, {{"name", name}});
    case Kind::MissesButDoubleHits:
      return phrase("oracle.note.misses_but_double_hits", language, {{"name", name}});
    case Kind::Tangent:
      return phrase("oracle.note.tangent", language, {{"name", name}});
    case Kind::ThroughEdge:
      return phrase("oracle.note.through_edge", language);
    case Kind::ThroughVertex:
      return phrase("oracle.note.through_vertex", language);
    case Kind::TError:
      return phrase("oracle.note.t_error", language,
                    {{"error", number(note.first, 3)}, {"bound", number(note.second, 3)}});
    case Kind::Primitives:
      return phrase("oracle.note.primitives", language,
                    {{"exact", std::to_string(long(note.first))},
                     {"double", std::to_string(long(note.second))}});
    case Kind::RecordedHit:
      return phrase("oracle.note.recorded_hit", language,
                    {{"recorded", number(note.first)}, {"exact", number(note.second)}});
  }
  return {};
}

/// "%.17g".
std::string full(double x) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

}  // namespace

std::string materialParameters(const Material& m, Language language) {
  std::string text;
  for (const auto& [key, value] : parameterList(m)) {
    if (!text.empty()) text += phrase("parameter.separator", language);
    const std::string name =
        key == "roughness"
            ? phrase("parameter.roughness", language, {{"distribution", toString(m.distribution)}})
            : phrase("parameter." + key, language);
    text += phrase("parameter.item", language, {{"name", name}, {"value", value}});
  }
  text += parameterSuffix(m, language);
  const std::string separator = phrase("parameter.separator", language);
  if (m.texture.active())
    text += separator +
            phrase("parameter.checker", language,
                   {{"scale", number(m.texture.scale)}, {"colour2", vec(m.texture.colour2)}});
  if (m.priority > 0)
    text += separator + phrase("parameter.item", language,
                               {{"name", phrase("parameter.priority", language)},
                                {"value", std::to_string(m.priority)}});
  if (m.isEmitter())
    text += separator +
            phrase("parameter.item", language,
                   {{"name", phrase("parameter.emits", language)}, {"value", vec(m.emission)}});
  return text;
}

std::vector<InspectorRow> inspectorRows(const RayInspection& r, Language language) {
  Rows out{language, {}};
  const RaySegment& s = r.segment;
  out.add("origin", vec(s.origin));
  out.add("direction", vec(s.direction));
  if (!r.lightName.empty()) out.add("light", out.say("inspector.quoted", {{"name", r.lightName}}));
  addEnd(out, r);

  // The nested volumes it is in, and the indices where it meets one.
  if (r.nested) out.add("inside", mediaWords(r, language));
  if (r.indices)
    out.add("indices", out.say(r.indices->entering ? "inspector.indices.entering"
                                                   : "inspector.indices.leaving",
                               {{"before", number(r.indices->before, 4)},
                                {"after", number(r.indices->after, 4)},
                                {"name", r.indices->name}}));

  // What it carried.
  out.add("weight", r.rateWeight ? out.say("inspector.weight.note",
                                           {{"weight", vec(s.weight)},
                                            {"note", rateWeightWords(*r.rateWeight, language)}})
                                 : vec(s.weight));
  out.add("pdf", s.pdf > 0.0 ? out.say("inspector.pdf", {{"pdf", number(s.pdf, 4)}})
                             : out.say("inspector.pdf.none"));
  out.add("throughput", vec(s.throughput));
  out.add("emitted", vec(s.emitted));
  out.add("radiance", vec(s.radiance));
  out.add("energy", number(r.energy, 4));
  const SceneNames names = namesOf(r);
  out.add("ended",
          out.say("inspector.ended", {{"clause", endClause(stepEventOf(s), names, language)},
                                      {"sentence", narrateStep(stepEventOf(s), names, language)}}));
  return out.rows;
}

std::vector<InspectorRow> oracleRows(const OracleCheck& check, Language language) {
  const auto field = [&](const std::string& key) {
    return phrase("oracle.field." + key, language);
  };
  const auto hitAt = [&](ExactClass c, double t) {
    return phrase(
        "oracle.hit_at", language,
        {{"class", phrase(std::string("oracle.class.") + toString(c), language)}, {"t", full(t)}});
  };
  const std::string miss = phrase("oracle.class.Miss", language);
  std::vector<InspectorRow> rows;
  const ExactResult& exact = check.comparison.exact;
  rows.push_back({field("exact"), exact.hit() ? hitAt(exact.classification, exact.t) : miss});
  if (exact.hit() && exact.tLower != exact.tUpper) {
    // The exact t is irrational or not a double: it lies between two adjacent doubles.
    rows.push_back({field("t_lower"), full(exact.tLower), true});
    rows.push_back({field("t_upper"), full(exact.tUpper), true});
  }
  const auto& floating = check.comparison.floating;
  rows.push_back({field("double"), floating ? hitAt(ExactClass::Hit, floating->t) : miss});
  if (check.comparison.agree && floating) {
    rows.push_back({field("t_error"), phrase("oracle.t_error", language,
                                             {{"error", number(check.comparison.tError, 3)},
                                              {"ulps", number(check.comparison.tErrorUlps, 3)}})});
    rows.push_back({field("bound"), number(check.tBound, 3)});
  }
  rows.push_back({field("margin"), exact.margin > 0 ? phrase("oracle.margin.robust", language,
                                                             {{"margin", number(exact.margin, 4)}})
                                                    : number(exact.margin, 4)});
  rows.push_back({field("cosine"), number(exact.cosine, 4)});
  rows.push_back(
      {field("verdict"),
       phrase(check.agrees ? "oracle.verdict.agrees" : "oracle.verdict.differs", language)});
  for (const OracleNote& note : check.notes)
    rows.push_back({"", noteWords(note, check.objectName, language)});
  return rows;
}

std::string rayText(const RayInspection& r, Language language) {
  const RaySegment& s = r.segment;
  std::string text = phrase("inspector.heading", language,
                            {{"id", std::to_string(s.id)},
                             {"kind", rayKindWord(s.kind, language)},
                             {"depth", std::to_string(s.depth)}});
  if (s.parent >= 0)
    text += phrase("inspector.heading.parent", language, {{"parent", std::to_string(s.parent)}});
  if (s.time != 0.0)
    text += phrase("inspector.heading.time", language, {{"time", number(s.time, 3)}});
  text += "\n";
  for (const InspectorRow& row : inspectorRows(r, language)) text += line(row, language);
  return text;
}

std::string oracleText(const RayInspection& r, Language language) {
  if (!r.oracle)
    return phrase(r.segment.hit ? "oracle.not_computed" : "oracle.no_hit", language) + "\n";
  std::string text = phrase("oracle.heading", language, {{"name", r.objectName}}) + "\n";
  for (const InspectorRow& row : oracleRows(*r.oracle, language)) text += line(row, language);
  return text;
}

std::string inspectorText(const RayInspection& r, Language language) {
  return rayText(r, language) + oracleText(r, language);
}

std::string crossingsText(const Scene& scene, const std::vector<SceneCrossing>& crossings,
                          Language language) {
  if (crossings.empty()) return phrase("crossing.none", language) + "\n";
  std::string text;
  for (const SceneCrossing& c : crossings) {
    const std::string name = c.object >= 0 && c.object < int(scene.objects.size())
                                 ? scene.objects[std::size_t(c.object)].name
                                 : std::string("?");
    const char* what = c.closed ? (c.entering ? "crossing.enters" : "crossing.leaves")
                                : (c.entering ? "crossing.front" : "crossing.back");
    text += phrase("crossing.line", language,
                   {{"t", number(c.t, 5)}, {"what", phrase(what, language)}, {"name", name}}) +
            "\n";
  }
  return text;
}

}  // namespace raylab

namespace raylab {

namespace {

/// printf's `format` of one double ("%.4g"), for the summary's figures.
std::string printed(const char* format, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

/// "Where: it hit 'ball', 2.5 units from where it started": where the ray went.
std::string whereWords(const RayInspection& r, Language language) {
  const RaySegment& s = r.segment;
  const std::string distance = printed("%.4g", r.distance);
  if (s.kind == RayKind::Shadow && s.endReason == EndReason::Occluded)
    return phrase("inspector.summary.blocked", language,
                  {{"object", r.objectName}, {"distance", distance}});
  if (s.kind == RayKind::Shadow)
    return phrase("inspector.summary.to_light", language, {{"distance", distance}});
  if (s.hit)
    return phrase("inspector.summary.hit", language,
                  {{"object", r.objectName}, {"distance", distance}});
  return phrase("inspector.summary.miss", language);
}

}  // namespace

std::string inspectionSummary(const RayInspection& r, double pixelEnergy, Language language) {
  const RaySegment& s = r.segment;
  const std::string carried =
      pixelEnergy > 0.0 ? phrase("inspector.summary.carried", language,
                                 {{"percent", printed("%.1f", 100.0 * r.energy / pixelEnergy)}})
                        : phrase("inspector.summary.carried_none", language);
  return phrase("inspector.summary.heading", language,
                {{"kind", rayKindWord(s.kind, language)}, {"depth", std::to_string(s.depth)}}) +
         "\n" + whereWords(r, language) + "\n" + carried + "\n" +
         phrase("inspector.summary.why", language,
                {{"reason", endReasonLabel(s.endReason, language)}}) +
         "\n";
}

}  // namespace raylab
