#include "scene/SphereLightSampler.h"

#include "raylab/core/Check.h"
#include "raylab/core/Sampling.h"

#include <algorithm>
#include <cmath>

#if defined(__x86_64__) && defined(__SSE2__) && (defined(__GNUC__) || defined(__clang__))
#define RAYLAB_SEPARATORS_SSE2 1
#include <emmintrin.h>
#else
#define RAYLAB_SEPARATORS_SSE2 0
#endif

#define RAYLAB_PLAN_INLINE inline __attribute__((always_inline))

namespace raylab {

namespace {

bool isStatic(const SceneObject& object) {
  return object.velocity.x == 0.0 && object.velocity.y == 0.0 && object.velocity.z == 0.0;
}

/// The round sphere of an object, or nullptr (other shapes, ellipsoids).
const Sphere* roundSphere(const SceneObject& object) {
  if (!object.shape || object.shape->kind() != ShapeKind::Sphere) return nullptr;
  const Sphere* sphere = static_cast<const Sphere*>(object.shape.get());
  return sphere->isRound() ? sphere : nullptr;
}

}  // namespace

SphereLightSampler::SphereLightSampler(const Scene& scene, int object) {
  const SceneObject& light = scene.objects[std::size_t(object)];
  m_sphere = roundSphere(light);
  RAYLAB_CHECK(m_sphere != nullptr);
  m_centre = m_sphere->centre();
  m_radius = m_sphere->radius();
  if (!isStatic(light)) return;

  classifySeparators(scene, object);
  packSeparatorColumns();
  nestCaps();
}

/// Classifies every other static round sphere S against the light: apart, around it, or
/// cutting it along a circle.
void SphereLightSampler::classifySeparators(const Scene& scene, int object) {
  const double R = m_radius;
  for (std::size_t j = 0; j < scene.objects.size(); ++j) {
    const SceneObject& other = scene.objects[j];
    const Sphere* s = roundSphere(other);
    if (int(j) == object || !s || !isStatic(other)) continue;
    const double rho = s->radius();
    const Vec3 between = s->centre() - m_centre;
    const double D = glm::length(between);
    Separator sep;
    sep.centre = s->centre();
    sep.radius2 = rho * rho;
    if (D >= R + rho) {
      sep.relation = Separator::Relation::Disjoint;
    } else if (D + R <= rho) {
      sep.relation = Separator::Relation::Encloses;
    } else if (D + rho <= R) {
      continue;  // S lies inside the light: it hides nothing of the outside surface
    } else {
      cutAlongCircle(sep, between, D, rho);
    }
    m_separators.push_back(sep);
  }
}

/// A separator S (radius rho, its centre `between` from the light's, D away) that cuts the
/// light along a circle: the axis and half-angle of the cap inside S, and each side's cap.
void SphereLightSampler::cutAlongCircle(Separator& sep, const Vec3& between, double D,
                                        double rho) const {
  const double R = m_radius;
  // Light points c + R n inside S satisfy |c + R n - s|^2 < rho^2, i.e.
  // n . axis > (D^2 + R^2 - rho^2) / (2 R D); (D - rho)(D + rho) keeps the precision
  // when S is huge (smallpt's walls have rho = 1e5).
  sep.relation = Separator::Relation::Cuts;
  sep.axis = between / D;
  sep.cosAlpha = std::clamp(((D - rho) * (D + rho) + R * R) / (2.0 * R * D), -1.0, 1.0);
  // The cap on each side; if it is smaller than a hemisphere, the ball through its rim
  // circle contains it.
  for (const int inside : {0, 1}) {
    const double cosAlpha = inside ? sep.cosAlpha : -sep.cosAlpha;
    if (!(cosAlpha > 0.0)) continue;
    const Vec3 axis = inside ? sep.axis : -sep.axis;
    sep.capCentre[inside] = m_centre + R * cosAlpha * axis;
    sep.capRadius2[inside] = R * R * std::max(0.0, 1.0 - cosAlpha * cosAlpha);
    // 1 - cos(half-angle) of the cap: (rho^2 - (D - R)^2) / (2 R D) inside S,
    // ((D + R)^2 - rho^2) / (2 R D) outside it, as products of sums (smallpt's cap is
    // 4.5e-4 high on the unit sphere).
    const double height = inside ? (rho - D + R) * (rho + D - R) / (2.0 * R * D)
                                 : (D + R - rho) * (D + R + rho) / (2.0 * R * D);
    sep.capHeight[inside] = std::clamp(height, 0.0, 1.0);
    sep.capArea[inside] = 2.0 * kPi * R * R * sep.capHeight[inside];
    const Frame frame(axis);
    sep.capS[inside] = frame.s;
    sep.capT[inside] = frame.t;
  }
}

/// The first 64 separators as columns and bit masks, for plan()'s loop without branches.
void SphereLightSampler::packSeparatorColumns() {
  for (std::size_t i = 0; i < std::min<std::size_t>(m_separators.size(), 64); ++i) {
    const Separator& sep = m_separators[i];
    m_sepX.push_back(sep.centre.x);
    m_sepY.push_back(sep.centre.y);
    m_sepZ.push_back(sep.centre.z);
    m_sepRadius2.push_back(sep.radius2);
    const std::uint64_t bit = std::uint64_t(1) << i;
    if (sep.relation == Separator::Relation::Disjoint) m_disjoint |= bit;
    if (sep.relation == Separator::Relation::Encloses) m_encloses |= bit;
    if (sep.relation == Separator::Relation::Cuts) {
      m_cuts.push_back(int(i));
      m_cutsMask |= bit;
      if (sep.capRadius2[0] >= 0.0) m_capOutside |= bit;
      if (sep.capRadius2[1] >= 0.0) m_capInside |= bit;
    }
  }
  // Padded to an even count (a radius^2 of -1 holds no point) for plan()'s pairs.
  if (m_sepX.size() % 2 != 0) {
    m_sepX.push_back(0.0);
    m_sepY.push_back(0.0);
    m_sepZ.push_back(0.0);
    m_sepRadius2.push_back(-1.0);
  }
}

/// Which caps lie within which: the cap of half-angle alpha around a lies within the one of
/// half-angle beta around b when angle(a, b) + alpha <= beta. (A wrong verdict would cost
/// efficiency only: sample() and pdf() skip the same checks, and shadow rays find what hides
/// a point.)
void SphereLightSampler::nestCaps() {
  const auto capAxis = [](const Separator& s, int side) { return side ? s.axis : -s.axis; };
  const auto halfAngle = [](const Separator& s, int side) {
    return std::acos(std::clamp(side ? s.cosAlpha : -s.cosAlpha, -1.0, 1.0));
  };
  for (const int i : m_cuts) {
    Separator& a = m_separators[std::size_t(i)];
    for (const int side : {0, 1}) {
      if (!(a.capRadius2[side] >= 0.0)) continue;  // only caps that are sampled by area
      for (const int j : m_cuts) {
        const Separator& b = m_separators[std::size_t(j)];
        for (const int sideJ : {0, 1}) {
          const Vec3 u = capAxis(a, side), v = capAxis(b, sideJ);
          const double between = std::atan2(glm::length(glm::cross(u, v)), glm::dot(u, v));
          if (j != i && between + halfAngle(a, side) + 1e-9 <= halfAngle(b, sideJ))
            a.within[side][sideJ] |= std::uint64_t(1) << j;
        }
      }
    }
  }
}

// plan()'s two parts, inlined into it (per shadow ray: a call each cost 11% of plan's
// instructions on smallpt).
RAYLAB_PLAN_INLINE std::uint64_t SphereLightSampler::insideMask(const Point3& ref) const {
  std::uint64_t inside = 0;
#if RAYLAB_SEPARATORS_SSE2
  // Two at a time, the same IEEE operations lane by lane (no FMA).
  const __m128d rx = _mm_set1_pd(ref.x), ry = _mm_set1_pd(ref.y), rz = _mm_set1_pd(ref.z);
  for (std::size_t i = 0; i < m_sepX.size(); i += 2) {
    const __m128d fx = _mm_sub_pd(rx, _mm_loadu_pd(&m_sepX[i]));
    const __m128d fy = _mm_sub_pd(ry, _mm_loadu_pd(&m_sepY[i]));
    const __m128d fz = _mm_sub_pd(rz, _mm_loadu_pd(&m_sepZ[i]));
    const __m128d f2 =
        _mm_add_pd(_mm_add_pd(_mm_mul_pd(fx, fx), _mm_mul_pd(fy, fy)), _mm_mul_pd(fz, fz));
    inside |= std::uint64_t(_mm_movemask_pd(_mm_cmplt_pd(f2, _mm_loadu_pd(&m_sepRadius2[i])))) << i;
  }
#else
  for (std::size_t i = 0; i < m_sepX.size(); ++i) {
    const double fx = ref.x - m_sepX[i], fy = ref.y - m_sepY[i], fz = ref.z - m_sepZ[i];
    inside |= std::uint64_t(fx * fx + fy * fy + fz * fz < m_sepRadius2[i]) << i;
  }
#endif
  return inside;
}

RAYLAB_PLAN_INLINE bool SphereLightSampler::preferCapArea(Plan& best, const Vec3& bestToCentre,
                                                          double bestDistance2) const {
  // The narrowest cone is a cap's ball. Of its directions, about the share cos(phi) reach
  // the cap, phi the angle at the cap between its axis and ref (the cap seen obliquely
  // fills less of its ball): sample the cap by area instead where cos(phi) is below 0.9
  // (kConeMinCos2; for smallpt's flat cap, everywhere but close under it).
  const Separator& s = m_separators[std::size_t(best.cap)];
  const Vec3 axis = best.capSide ? s.axis : -s.axis;
  const double along = -glm::dot(bestToCentre, axis);  // ref - capCentre along the axis
  if (!(along > 0.0) || along * along < kConeMinCos2 * bestDistance2) {
    best.mode = Plan::Mode::CapArea;
    // Separators whose side ref is on contains the whole cap cannot drop its points.
    const int side = best.capSide;
    best.check &= ~((best.inside & s.within[side][1]) | (~best.inside & s.within[side][0]));
    return true;
  }
  return false;
}

SphereLightSampler::Plan SphereLightSampler::plan(const Point3& ref) const {
  // One named result, returned from everywhere, so that it is built in the caller's
  // place: copying it out through the stack cost store-forwarding stalls.
  // best.mode stays Invisible until the end (or Area, returned at once).
  Plan best;
  // From inside (or on) the light there is no cone: area sampling.
  const Vec3 toCentre = m_centre - ref;
  const double centreDistance2 = glm::dot(toCentre, toCentre);
  if (!(centreDistance2 > m_radius * m_radius)) {
    best.mode = Plan::Mode::Area;
    return best;
  }
  // The cone of directions towards a ball (centre, radius) seen from outside it has
  // sin^2 theta_max = radius^2 / distance^2: keep the ball with the smallest ratio (the
  // narrowest cone), compared without dividing, and take square roots once, for it alone.
  Vec3 bestToCentre = toCentre;
  double bestDistance2 = centreDistance2;
  double bestRadius2 = m_radius * m_radius;
  const auto consider = [&](int i, int side) {
    const Separator& s = m_separators[std::size_t(i)];
    const double radius2 = s.capRadius2[side];
    const Vec3 v = s.capCentre[side] - ref;
    const double distance2 = glm::dot(v, v);
    if (!(distance2 > radius2)) return;
    if (radius2 * bestDistance2 < bestRadius2 * distance2) {
      bestRadius2 = radius2;
      bestToCentre = v;
      bestDistance2 = distance2;
      best.cap = i;
      best.capSide = side;
    }
  };
  if (m_separators.size() <= 64) {
    // Which separators ref is inside (isInside's operations), then the verdicts as masks,
    // and the caps' balls on ref's side considered in the same order as the loop below.
    const std::uint64_t inside = insideMask(ref);
    if ((inside & m_disjoint) != 0 || (~inside & m_encloses) != 0) return best;
    best.inside = inside;
    best.check = m_cutsMask;
    for (std::uint64_t caps = (inside & m_capInside) | (~inside & m_capOutside); caps != 0;
         caps &= caps - 1) {
      const int i = __builtin_ctzll(caps);
      consider(i, int((inside >> i) & 1));
    }
  }
  for (std::size_t i = m_separators.size() <= 64 ? m_separators.size() : 0; i < m_separators.size();
       ++i) {
    const Separator& s = m_separators[i];
    const bool inside = isInside(s, ref);
    if (inside && i < 64) best.inside |= std::uint64_t(1) << i;
    switch (s.relation) {
      case Separator::Relation::Disjoint:
        if (inside) return best;  // the light is on the other side of S
        break;
      case Separator::Relation::Encloses:
        if (!inside) return best;
        break;
      case Separator::Relation::Cuts:
        if (s.capRadius2[inside] >= 0.0) consider(int(i), int(inside));
        break;
    }
  }
  if (best.cap >= 0 && preferCapArea(best, bestToCentre, bestDistance2)) return best;
  best.mode = Plan::Mode::Cone;
  // cos theta_max = sqrt(distance^2 - radius^2) / distance; one division for it and the axis.
  const double inverseDistance = 1.0 / std::sqrt(bestDistance2);
  best.cosThetaMax =
      std::min(1.0, std::sqrt(std::max(0.0, bestDistance2 - bestRadius2)) * inverseDistance);
  best.axis = bestToCentre * inverseDistance;
  best.centreOffset = -toCentre;
  best.c = centreDistance2 - m_radius * m_radius;
  return best;
}

bool SphereLightSampler::visibleSide(const Plan& plan, const Point3& ref, const Normal3& n) const {
  if (m_separators.size() <= 64) {
    for (std::uint64_t check = plan.check; check != 0; check &= check - 1) {
      const int i = __builtin_ctzll(check);
      const Separator& s = m_separators[std::size_t(i)];
      const bool inside = (plan.inside >> i) & 1;
      const double side = glm::dot(n, s.axis) - s.cosAlpha;
      if (inside ? side < 0.0 : side > 0.0) return false;
    }
    return true;
  }
  for (std::size_t i = 0; i < m_separators.size(); ++i) {
    const Separator& s = m_separators[i];
    if (s.relation != Separator::Relation::Cuts) continue;
    const bool inside = i < 64 ? (plan.inside >> i) & 1 : isInside(s, ref);
    const double side = glm::dot(n, s.axis) - s.cosAlpha;  // > 0: the light point is inside S
    if (inside ? side < 0.0 : side > 0.0) return false;
  }
  return true;
}

bool SphereLightSampler::sample(const Point3& ref, const Vec2& u, LightSample& ls) const {
  const Plan p = plan(ref);
  switch (p.mode) {
    case Plan::Mode::Invisible:
      return false;
    case Plan::Mode::Area: {
      // Uniform on the surface, converted to solid angle (only the outside emits, so from
      // inside this finds nothing; it keeps the density well defined).
      if (!lightSampleFromArea(m_sphere->sampleArea(u), ref, ls)) return false;
      break;
    }
    case Plan::Mode::CapArea: {
      // Uniform in area on the cap (Archimedes: 1 - cos(theta) uniform in [0, height]),
      // converted to solid angle; points facing away from ref or hidden by another
      // separating sphere are dropped.
      const Separator& s = m_separators[std::size_t(p.cap)];
      const int side = p.capSide;
      const double oneMinusCos = u.x * s.capHeight[side];
      const double sinTheta = std::sqrt(oneMinusCos * (2.0 - oneMinusCos));
      const Vec2 cs = cosSinTurn(u.y);
      const Vec3 axis = side ? s.axis : -s.axis;
      ShapeSample point;
      point.n = (sinTheta * cs.x) * s.capS[side] + (sinTheta * cs.y) * s.capT[side] +
                (1.0 - oneMinusCos) * axis;
      if (!visibleSide(p, ref, point.n)) return false;
      point.p = m_centre + m_radius * point.n;
      point.pdfArea = 1.0 / s.capArea[side];
      if (!lightSampleFromArea(point, ref, ls)) return false;
      break;
    }
    case Plan::Mode::Cone: {
      // A direction uniform in the cone, followed to its first hit on the light.
      const Vec3 w = Frame(p.axis).toWorld(sampleUniformCone(u, p.cosThetaMax));
      // w is a unit vector and ref is outside the light (c > 0), so t^2 + 2 b t + c = 0 has
      // two roots of one sign, positive when w heads towards the centre (b < 0); the nearer
      // one as c / (-b + sqrt(b^2 - c)), free of cancellation. (One square root and one
      // division, where the general ray-sphere test takes two and three.)
      const double b = glm::dot(p.centreOffset, w);
      const double discriminant = b * b - p.c;
      if (!(b < 0.0) || !(discriminant >= 0.0))
        return false;  // a cap's cone is wider
                       // than the cap
      const double t = p.c / (std::sqrt(discriminant) - b);
      const Vec3 radial = p.centreOffset + t * w;
      ls.n = radial * (1.0 / glm::length(radial));
      // Drop points that a separating sphere hides from ref.
      if (!visibleSide(p, ref, ls.n)) return false;
      // The point on the surface; the direction and distance to it are w and t (to
      // rounding: the point is projected onto the sphere).
      ls.p = m_centre + m_radius * ls.n;
      ls.wi = w;
      ls.distance = t;
      if (!(-glm::dot(ls.n, w) > 0.0)) return false;
      ls.pdf = uniformConePdf(p.cosThetaMax);
      break;
    }
  }
  return ls.pdf > 0.0 && std::isfinite(ls.pdf);
}

double SphereLightSampler::pdf(const Point3& ref, const Point3& point, const Normal3& n) const {
  const Plan p = plan(ref);
  if (p.mode == Plan::Mode::Invisible) return 0.0;
  // Only the front side, facing ref, is ever sampled.
  const Vec3 d = point - ref;
  const double distance2 = glm::dot(d, d);
  if (!(distance2 > 0.0)) return 0.0;
  const double cosLight = -glm::dot(n, d) / std::sqrt(distance2);
  if (!(cosLight > 0.0)) return 0.0;
  if (p.mode == Plan::Mode::Area) return m_sphere->pdfArea(point) * distance2 / cosLight;
  if (p.mode == Plan::Mode::CapArea) {
    // Every visible point lies in the sampled cap, where the area density is uniform.
    if (!visibleSide(p, ref, n)) return 0.0;
    return distance2 / (m_separators[std::size_t(p.cap)].capArea[p.capSide] * cosLight);
  }
  // Cone: every visible point lies in the chosen cone, where the density is uniform.
  return visibleSide(p, ref, n) ? uniformConePdf(p.cosThetaMax) : 0.0;
}

}  // namespace raylab
