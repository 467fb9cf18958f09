// Tracing one pixel sample with a student's pieces and judging every call of them against
// the exact oracle (StudentHooks.h).

#include "raylab/core/StudentHooks.h"

#include "integrators/TraceSteps.h"
#include "raylab/core/ExactOracle.h"
#include "raylab/core/Tracer.h"

#include <algorithm>
#include <cmath>

namespace raylab {

const char* toString(Verdict verdict) {
  switch (verdict) {
    case Verdict::NotJudged:
      return "not_judged";
    case Verdict::Agrees:
      return "agrees";
    case Verdict::OffByUlps:
      return "off_by_ulps";
    case Verdict::SpuriousHit:
      return "spurious_hit";
    case Verdict::MissedHit:
      return "missed_hit";
    case Verdict::WrongHit:
      return "wrong_hit";
    case Verdict::NonFinite:
      return "non_finite";
    case Verdict::Exception:
      return "exception";
    case Verdict::WrongWeight:
      return "wrong_weight";
  }
  return "?";
}

bool verdictPasses(Verdict verdict) {
  return verdict == Verdict::NotJudged || verdict == Verdict::Agrees ||
         verdict == Verdict::OffByUlps;
}

namespace {

/// |a - b| in ulps of b (the spacing of doubles just above |b|).
double ulpsBetween(double a, double b) {
  const double m = std::abs(b);
  const double ulp = std::nextafter(m, kInfinity) - m;
  return std::abs(a - b) / ulp;
}

}  // namespace

void judgeCall(const Scene& scene, StudentCall& call) {
  judgeCall(*scene.objects[std::size_t(call.object)].shape, call);
}

void judgeCall(const Shape& shape, StudentCall& call) {
  if (!call.error.empty()) {
    call.verdict = Verdict::Exception;
    return;
  }
  if (call.student && !std::isfinite(*call.student)) {
    call.verdict = Verdict::NonFinite;
    return;
  }
  // The exact answer, and the engine's own double answer, whose error sets the tolerance.
  const OracleComparison engine = ExactOracle::compare(shape, call.query);
  call.exactHit = engine.exact.hit();
  call.exact = engine.exact.t;
  call.tangent = engine.exact.classification != ExactClass::Hit && call.exactHit;
  const bool gave = call.student.has_value();
  const bool hits = gave && *call.student >= call.query.tMin && *call.student <= call.query.tMax;
  const bool engineHits = engine.floating.has_value();
  // Near a tangent or an edge the double answer may fall either way: a student who agrees
  // with the engine's double answer there is right.
  const bool eitherWay = call.tangent || engineHits != call.exactHit;
  if (gave && !hits) {
    // A t outside [tMin, tMax] (behind the origin, beyond the light): the engine ignores it,
    // but the contract asks for None there.
    call.verdict = call.exactHit && !eitherWay ? Verdict::WrongHit : Verdict::SpuriousHit;
    return;
  }
  if (!hits) {
    call.verdict = !call.exactHit || eitherWay ? Verdict::Agrees : Verdict::MissedHit;
    return;
  }
  if (!call.exactHit) {
    call.verdict = eitherWay ? Verdict::Agrees : Verdict::SpuriousHit;
    return;
  }
  call.ulps = ulpsBetween(*call.student, call.exact);
  const double tolerance = std::max(kAgreeUlps, 2.0 * engine.tErrorUlps);
  if (call.ulps <= tolerance)
    call.verdict = Verdict::Agrees;
  else if (call.ulps <= kOffUlps)
    call.verdict = Verdict::OffByUlps;
  else
    call.verdict = Verdict::WrongHit;
}

namespace {

/// The student's tree, each call tagged with the ray whose step made it.
PixelTrace traceWithLog(const Tracer& tracer, int x, int y, int sample,
                        const std::optional<Ray>& root, StudentLog& log) {
  return traceSteps(tracer, x, y, sample, TraceLimits{}, root, [&log](Stepper& stepper) {
    const int id = stepper.queue().front().id;
    const std::size_t before = log.calls.size();
    stepper.step();
    for (std::size_t i = before; i < log.calls.size(); ++i) log.calls[i].ray = id;
  });
}

}  // namespace

StudentTrace traceStudent(const Scene& scene, const RenderSettings& settings,
                          const StudentHooks& hooks, int x, int y, int sample,
                          std::optional<Ray> root) {
  StudentTrace out;
  out.reference = root ? traceRay(scene, settings, *root, x, y, sample)
                       : tracePixel(scene, settings, x, y, sample);
  StudentLog log;
  const std::shared_ptr<Scene> copy = studentScene(scene, hooks, &log);
  const Tracer tracer(*copy, settings);
  out.student = traceWithLog(tracer, x, y, sample, root, log);
  out.calls = std::move(log.calls);

  // Judge every call; a ray's verdict is the worst of its calls (the first such call).
  out.verdicts.resize(out.student.tree.segments.size());
  for (std::size_t i = 0; i < out.calls.size(); ++i) {
    StudentCall& call = out.calls[i];
    judgeCall(scene, call);
    if (call.ray < 0 || std::size_t(call.ray) >= out.verdicts.size()) continue;
    RayVerdict& v = out.verdicts[std::size_t(call.ray)];
    if (int(call.verdict) > int(v.verdict)) v = RayVerdict{call.verdict, int(i)};
  }
  for (std::size_t r = 0; r < out.verdicts.size(); ++r)
    if (!verdictPasses(out.verdicts[r].verdict)) {
      out.firstDivergent = int(r);
      break;
    }
  return out;
}

}  // namespace raylab
