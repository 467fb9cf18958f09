// The inspector's words: the number formats, the ray's lines and the oracle block.
#include "inspect/InspectorFormat.h"
#include "raylab/core/RayInspector.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace raylab {

namespace inspect {

std::string vec(const Vec3& v) {
  // Components below 1e-12 of the largest are rounding (a point reconstructed as origin +
  // t d): shown as 0, so (0, 5, 4.441e-16) reads (0, 5, 0).
  const double largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  const auto shown = [&](double x) { return std::abs(x) < 1e-12 * largest ? 0.0 : x; };
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "(%.4g, %.4g, %.4g)", shown(v.x), shown(v.y), shown(v.z));
  return buffer;
}

std::string number(double x, int digits) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, x);
  return buffer;
}

/// How a Mirror's or a classic material's two rays are weighted: ", weights kr R, kt (1 - R)
/// (Schlick's Fresnel)" with Fresnel, nothing with the constant rates.
std::string rateWeights(const Material& m) {
  if (m.rateFresnel == FresnelModel::None) return "";
  return m.rateFresnel == FresnelModel::Schlick ? ", weights kr R, kt (1 - R) (Schlick's Fresnel)"
                                                : ", weights kr R, kt (1 - R) (Fresnel)";
}

std::string materialParameters(const Material& m) {
  std::string text;
  switch (m.type) {
    case MaterialType::Diffuse:
      text = "albedo " + vec(m.colour);
      break;
    case MaterialType::Mirror:
      text = "tint " + vec(m.colour) + ", reflection rate " + number(m.reflectionRate) +
             ", refraction rate " + number(m.refractionRate) + ", ior " + number(m.ior) +
             rateWeights(m);
      break;
    case MaterialType::Dielectric:
      text = "tint " + vec(m.colour) + ", ior " + number(m.ior) +
             (m.fresnel == FresnelModel::Schlick ? " (Schlick's Fresnel)" : " (Fresnel)");
      break;
    case MaterialType::Glossy:
      text = "colour " + vec(m.colour) + ", Phong exponent " + number(m.exponent) +
             ", specular share " + number(m.specular);
      break;
    case MaterialType::Phong:
    case MaterialType::BlinnPhong:
      text = "colour " + vec(m.colour) + ", ambient " + vec(m.ambient) + ", kd " +
             number(m.diffuse) + ", ks " + number(m.specular) + ", shininess " +
             number(m.exponent) + ", kr " + number(m.reflectionRate) + ", kt " +
             number(m.refractionRate) + ", attenuation " + vec(m.attenuation) + rateWeights(m);
      break;
    case MaterialType::RoughConductor:
      text = "F0 " + vec(m.colour) + ", " + toString(m.distribution) + " roughness " +
             number(m.roughness);
      break;
    case MaterialType::RoughDielectric:
      text = "tint " + vec(m.colour) + ", ior " + number(m.ior) + ", " + toString(m.distribution) +
             " roughness " + number(m.roughness) + " (" + toString(m.fresnel) + " Fresnel)";
      break;
    case MaterialType::Plastic:
      text = "base " + vec(m.colour) + ", coating ior " + number(m.ior) + ", " +
             toString(m.distribution) + " roughness " + number(m.roughness) + " (" +
             toString(m.fresnel) + " Fresnel)";
      break;
  }
  if (m.texture.active())
    text += ", checker texture (cubes of side " + number(m.texture.scale) + ", second colour " +
            vec(m.texture.colour2) + ")";
  if (m.priority > 0) text += ", priority " + std::to_string(m.priority);
  if (m.isEmitter()) text += ", emits " + vec(m.emission);
  return text;
}

void line(std::ostringstream& out, const char* label, const std::string& value) {
  char buffer[24];
  std::snprintf(buffer, sizeof buffer, "  %-12s", label);
  out << buffer << value << "\n";
}

}  // namespace inspect

using inspect::line;
using inspect::number;
using inspect::vec;

std::string MaterialSummary::toString() const {
  return "'" + name + "' " + raylab::toString(type) + (emitter ? " light" : "") + ": " + parameters;
}

std::string OracleCheck::toString() const {
  std::ostringstream out;
  const ExactResult& exact = comparison.exact;
  char buffer[160];
  if (exact.hit()) {
    std::snprintf(buffer, sizeof buffer, "%s, t = %.17g", raylab::toString(exact.classification),
                  exact.t);
    line(out, "exact", buffer);
    if (exact.tLower != exact.tUpper) {
      // The exact t is irrational or not a double: it lies between two adjacent doubles.
      std::snprintf(buffer, sizeof buffer, "%.17g", exact.tLower);
      line(out, "  t >", buffer);
      std::snprintf(buffer, sizeof buffer, "%.17g", exact.tUpper);
      line(out, "  t <", buffer);
    }
  } else {
    line(out, "exact", "Miss");
  }
  if (comparison.floating) {
    std::snprintf(buffer, sizeof buffer, "Hit, t = %.17g", comparison.floating->t);
    line(out, "double", buffer);
  } else {
    line(out, "double", "Miss");
  }
  if (comparison.agree && comparison.floating) {
    std::snprintf(buffer, sizeof buffer, "%.3g (%.3g ulp)", comparison.tError,
                  comparison.tErrorUlps);
    line(out, "|t error|", buffer);
    line(out, "bound", number(tBound, 3));
  }
  line(out, "margin", number(exact.margin, 4) + (exact.margin > 0 ? " (robust)" : ""));
  line(out, "cosine", number(exact.cosine, 4));
  line(out, "verdict", agrees ? "agrees with double precision" : "differs from double precision:");
  for (const std::string& note : notes) out << "    " << note << "\n";
  return out.str();
}

std::string RayInspection::rayText() const {
  std::ostringstream out;

  // Which ray: kind, depth and family.
  out << "Ray #" << segment.id << ": " << raylab::toString(segment.kind) << " ray, depth "
      << segment.depth;
  if (segment.parent >= 0) out << ", child of #" << segment.parent;
  if (segment.time != 0.0) out << ", time " << number(segment.time, 3);
  out << "\n";
  line(out, "origin", vec(segment.origin));
  line(out, "direction", vec(segment.direction));
  if (!lightName.empty()) line(out, "light", "'" + lightName + "'");

  // Where it ended.
  if (segment.hit) {
    line(out, segment.kind == RayKind::Shadow ? "blocked at" : "hit point", vec(segment.endPoint));
    line(out, "distance", number(distance));
    line(out, "normal", vec(segment.normal));
    // A smooth surface shades with another normal, interpolated from its vertices'.
    if (!isZero(segment.shadingNormal) && segment.shadingNormal != segment.normal)
      line(out, "shading", vec(segment.shadingNormal) + " interpolated");
    line(out, "object", "'" + objectName + "'");
    if (material) {
      line(out, "material",
           "'" + material->name + "' (" + raylab::toString(material->type) +
               (material->emitter ? ", a light)" : ")"));
      line(out, "parameters", material->parameters);
    }
    if (segment.kind == RayKind::Shadow) line(out, "light point", vec(lightPoint));
  } else if (segment.kind == RayKind::Shadow && segment.endReason == EndReason::ReachedLight) {
    line(out, "light point", vec(segment.endPoint));
    line(out, "distance", number(distance));
  } else {
    line(out, "hit", segment.endReason == EndReason::Pending ? "not traced yet" : "nothing");
  }

  // The nested volumes it is in, and the indices where it meets one.
  if (!media.empty()) line(out, "inside", media);
  if (!indices.empty()) line(out, "indices", indices);

  // What it carried.
  line(out, "weight", vec(segment.weight) + (weightNote.empty() ? "" : " = " + weightNote));
  line(out, "pdf", segment.pdf > 0.0 ? number(segment.pdf, 4) + " per sr" : "none (deterministic)");
  line(out, "throughput", vec(segment.throughput));
  line(out, "emitted", vec(segment.emitted));
  line(out, "radiance", vec(segment.radiance));
  line(out, "energy", number(energy, 4));
  line(out, "ended", ended);
  return out.str();
}

std::string RayInspection::oracleText() const {
  // The exact oracle next to double precision.
  std::ostringstream out;
  if (oracle) {
    out << "Exact oracle (CGAL) on '" << objectName << "':\n";
    out << oracle->toString();
  } else if (segment.hit) {
    out << "Exact oracle: not computed\n";
  } else {
    out << "Exact oracle: no hit to check\n";
  }
  return out.str();
}

}  // namespace raylab
