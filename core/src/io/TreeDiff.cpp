#include "raylab/core/TreeDiff.h"

#include "raylab/core/Phrases.h"
#include "raylab/core/RayTreeJson.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <vector>

namespace raylab {

namespace {

bool close(double a, double b) {
  if (a == b) return true;  // equal infinities too
  if (!std::isfinite(a) || !std::isfinite(b)) return false;
  return std::abs(a - b) <= kTreeDiffTolerance * std::max({1.0, std::abs(a), std::abs(b)});
}

bool sameVec(const Vec3& u, const Vec3& v) {
  return close(u.x, v.x) && close(u.y, v.y) && close(u.z, v.z);
}

std::string number(double x) {
  std::ostringstream out;
  out.precision(17);
  out << x;
  return out.str();
}

std::string vector(const Vec3& v) {
  return "[" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + "]";
}

/// One compared field: its JSON name, whether a and b agree, and both values as text.
struct FieldCheck {
  const char* name;
  std::function<bool(const RaySegment&, const RaySegment&)> agree;
  std::function<std::string(const RaySegment&)> text;
};

FieldCheck vecField(const char* name, Vec3 RaySegment::*member) {
  return {
      name,
      [member](const RaySegment& a, const RaySegment& b) { return sameVec(a.*member, b.*member); },
      [member](const RaySegment& s) { return vector(s.*member); }};
}

template <typename T>
FieldCheck exactField(const char* name, T RaySegment::*member,
                      std::function<std::string(const T&)> text) {
  return {name,
          [member](const RaySegment& a, const RaySegment& b) { return a.*member == b.*member; },
          [member, text](const RaySegment& s) { return text(s.*member); }};
}

const std::vector<FieldCheck>& fieldChecks() {
  static const std::vector<FieldCheck> checks = [] {
    const auto integer = [](const int& i) { return std::to_string(i); };
    std::vector<FieldCheck> c;
    c.push_back(exactField<RayKind>("kind", &RaySegment::kind,
                                    [](const RayKind& k) { return std::string(toString(k)); }));
    c.push_back(exactField<int>("parent", &RaySegment::parent, integer));
    c.push_back(exactField<int>("depth", &RaySegment::depth, integer));
    c.push_back(vecField("origin", &RaySegment::origin));
    c.push_back(vecField("direction", &RaySegment::direction));
    c.push_back(exactField<bool>("hit", &RaySegment::hit,
                                 [](const bool& h) { return std::string(h ? "true" : "false"); }));
    c.push_back(exactField<int>("object", &RaySegment::object, integer));
    c.push_back(vecField("end_point", &RaySegment::endPoint));
    c.push_back(vecField("normal", &RaySegment::normal));
    c.push_back(exactField<EndReason>("end_reason", &RaySegment::endReason, [](const EndReason& r) {
      return std::string(RayTreeJson::endReasonName(r));
    }));
    c.push_back(vecField("weight", &RaySegment::weight));
    c.push_back({"pdf",
                 [](const RaySegment& a, const RaySegment& b) { return close(a.pdf, b.pdf); },
                 [](const RaySegment& s) { return number(s.pdf); }});
    c.push_back(vecField("throughput", &RaySegment::throughput));
    c.push_back(vecField("emitted", &RaySegment::emitted));
    c.push_back(vecField("radiance", &RaySegment::radiance));
    return c;
  }();
  return checks;
}

}  // namespace

std::optional<TreeDifference> firstTreeDifference(const RayTree& ours, const RayTree& theirs) {
  const std::size_t common = std::min(ours.segments.size(), theirs.segments.size());
  for (std::size_t i = 0; i < common; ++i) {
    const RaySegment& a = ours.segments[i];
    const RaySegment& b = theirs.segments[i];
    for (const FieldCheck& check : fieldChecks())
      if (!check.agree(a, b))
        return TreeDifference{int(i), check.name, check.text(a), check.text(b)};
  }
  if (ours.segments.size() == theirs.segments.size()) return std::nullopt;
  return TreeDifference{int(common), "rays", std::to_string(ours.segments.size()),
                        std::to_string(theirs.segments.size())};
}

std::string describe(const TreeDifference& d, Language language) {
  if (d.field == "rays")
    return phrase("tree_diff.rays", language,
                  {{"ours", d.ours}, {"theirs", d.theirs}, {"ray", std::to_string(d.ray)}});
  return phrase(
      "tree_diff.field", language,
      {{"ray", std::to_string(d.ray)}, {"field", d.field}, {"ours", d.ours}, {"theirs", d.theirs}});
}

namespace {

/// The verdict of a ray from its own geometry and energy, leaving out what it may inherit
/// from its parent (throughput) or its children (radiance).
Verdict judgeGeometry(const RaySegment& a, const RaySegment& b) {
  if (a.kind != b.kind || a.parent != b.parent || a.depth != b.depth ||
      !sameVec(a.origin, b.origin) || !sameVec(a.direction, b.direction))
    return Verdict::WrongHit;
  if (a.hit != b.hit) return a.hit ? Verdict::MissedHit : Verdict::SpuriousHit;
  if (a.object != b.object || !sameVec(a.endPoint, b.endPoint) ||
      (a.hit && !sameVec(a.normal, b.normal)))
    return Verdict::WrongHit;
  const bool ownEnergy = sameVec(a.weight, b.weight) && close(a.pdf, b.pdf) &&
                         sameVec(a.emitted, b.emitted) && a.endReason == b.endReason;
  return ownEnergy ? Verdict::Agrees : Verdict::WrongWeight;
}

}  // namespace

std::vector<Verdict> judgeTree(const RayTree& reference, const RayTree& theirs) {
  const std::size_t n = theirs.segments.size();
  const std::size_t common = std::min(n, reference.segments.size());
  std::vector<Verdict> verdicts(n, Verdict::SpuriousHit);  // rays the reference lacks
  const auto valid = [n](int id) { return id >= 0 && std::size_t(id) < n; };
  for (std::size_t i = 0; i < common; ++i) {
    const RaySegment &a = reference.segments[i], &b = theirs.segments[i];
    Verdict v = judgeGeometry(a, b);
    // Throughput is inherited: it is this ray's fault only when its parent's agrees.
    const bool parentThroughputAgrees =
        !valid(b.parent) || std::size_t(b.parent) >= common ||
        sameVec(reference.segments[std::size_t(b.parent)].throughput,
                theirs.segments[std::size_t(b.parent)].throughput);
    if (v == Verdict::Agrees && parentThroughputAgrees && !sameVec(a.throughput, b.throughput))
      v = Verdict::WrongWeight;
    verdicts[i] = v;
  }
  // Radiance is gathered from the children: it is this ray's fault only when all of them
  // agree. Children come after parents, so a pass in reverse id order sees them first. A ray
  // whose children theirs lacks keeps its own radiance difference: no ray of theirs can
  // carry it.
  std::vector<bool> childDiffers(n, false);
  for (std::size_t j = n; j-- > 0;) {
    if (j < common && verdicts[j] == Verdict::Agrees && !childDiffers[j] &&
        !sameVec(reference.segments[j].radiance, theirs.segments[j].radiance))
      verdicts[j] = Verdict::WrongWeight;
    const int parent = theirs.segments[j].parent;
    if (verdicts[j] != Verdict::Agrees && valid(parent)) childDiffers[std::size_t(parent)] = true;
  }
  return verdicts;
}

}  // namespace raylab
