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
  return {name,
          [member](const RaySegment& a, const RaySegment& b) {
            const Vec3 &u = a.*member, &v = b.*member;
            return close(u.x, v.x) && close(u.y, v.y) && close(u.z, v.z);
          },
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

}  // namespace raylab
