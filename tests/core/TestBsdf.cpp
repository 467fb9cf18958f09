// Materials against hand-computed optics: mirror directions, Snell's law, Fresnel,
// total internal reflection, energy and reciprocity, and the consistency of sample()
// with eval() / pdf(). Expected values are written beside each check.
#include "raylab/core/Bsdf.h"
#include "raylab/core/Sampler.h"
#include "raylab/core/Sampling.h"

#include <gtest/gtest.h>

#include <cmath>

namespace raylab {
namespace {

constexpr double kGlass = 1.5;

/// A hit at the origin with outward normal n, seen from direction wo.
SurfaceInteraction hitAt(const Normal3& n, const Vec3& wo) {
  SurfaceInteraction si;
  si.t = 1.0;
  si.p = Point3(0.0);
  si.n = glm::normalize(n);
  si.frontFace = glm::dot(wo, si.n) > 0.0;
  return si;
}

/// The unit direction at `degrees` from the normal +y, tilted towards -x (so the mirror
/// direction leans towards +x).
Vec3 fromNormal(double degrees) {
  const double a = radians(degrees);
  return {-std::sin(a), std::cos(a), 0.0};
}

double angleDegrees(const Vec3& a, const Vec3& b) {
  return std::acos(glm::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0)) * 180.0 /
         kPi;
}

Material material(MaterialType type) {
  Material m;
  m.type = type;
  return m;
}

/// Textbook Fresnel with the indices written out (Hecht, Optics, 4.32-4.34).
double fresnelTextbook(double thetaI, double n1, double n2) {
  const double sinT = n1 / n2 * std::sin(thetaI);
  if (sinT >= 1.0) return 1.0;
  const double ci = std::cos(thetaI), ct = std::sqrt(1.0 - sinT * sinT);
  const double rs = (n1 * ci - n2 * ct) / (n1 * ci + n2 * ct);
  const double rp = (n2 * ci - n1 * ct) / (n2 * ci + n1 * ct);
  return 0.5 * (rs * rs + rp * rp);
}

Vec3 randomUpper(Sampler& rng, const Normal3& n) {
  return Frame(n).toWorld(sampleCosineHemisphere(rng.next2D()));
}

TEST(Bsdf, 01_ReflectGivesTheMirrorDirection) {
  // 45 degrees onto the floor: (-1, 1, 0)/sqrt2 reflects to (1, 1, 0)/sqrt2.
  const Vec3 wo = glm::normalize(Vec3(-1, 1, 0));
  const Vec3 r = bsdf::reflect(wo, {0, 1, 0});
  EXPECT_NEAR(glm::length(r - glm::normalize(Vec3(1, 1, 0))), 0.0, 1e-15);
  // Angle in equals angle out, and the three vectors are coplanar, for any normal.
  Sampler rng(1, 0, 0, 0);
  for (int i = 0; i < 1000; ++i) {
    const Vec3 n = sampleUniformSphere(rng.next2D());
    const Vec3 w = sampleUniformSphere(rng.next2D());
    const Vec3 m = bsdf::reflect(w, n);
    EXPECT_NEAR(glm::length(m), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(m, n), glm::dot(w, n), 1e-12);
    EXPECT_NEAR(glm::dot(glm::cross(w, n), m), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(bsdf::reflect(m, n) - w), 0.0, 1e-12);
  }
}

TEST(Bsdf, 02_RefractionAt45DegreesIntoGlass) {
  // Snell: sin(theta_t) = sin(45) / 1.5, theta_t = asin(0.4714) = 28.1255 degrees, on the
  // far side of the normal, continuing in the same tangential direction (+x).
  const Vec3 wo = fromNormal(45.0);
  const auto wt = bsdf::refract(wo, {0, 1, 0}, 1.0 / kGlass);
  ASSERT_TRUE(wt.has_value());
  const double expected = std::asin(std::sin(radians(45.0)) / kGlass) * 180.0 / kPi;
  EXPECT_NEAR(expected, 28.1255, 1e-4);
  EXPECT_NEAR(angleDegrees(*wt, {0, -1, 0}), expected, 1e-10);
  EXPECT_GT(wt->x, 0.0);
  EXPECT_NEAR(wt->z, 0.0, 1e-15);
  EXPECT_NEAR(glm::length(*wt), 1.0, 1e-15);
  // Normal incidence goes straight through.
  const auto straight = bsdf::refract({0, 1, 0}, {0, 1, 0}, 1.0 / kGlass);
  ASSERT_TRUE(straight.has_value());
  EXPECT_NEAR(glm::length(*straight - Vec3(0, -1, 0)), 0.0, 1e-15);
}

TEST(Bsdf, 03_RefractionIsReversible) {
  // Light retraces its path: a ray sent back along the transmitted direction leaves the
  // glass along wo.
  for (double deg : {0.0, 10.0, 30.0, 45.0, 60.0, 80.0, 89.0}) {
    const Vec3 wo = fromNormal(deg);
    const auto in = bsdf::refract(wo, {0, 1, 0}, 1.0 / kGlass);
    ASSERT_TRUE(in.has_value());
    // The reversed ray travels along -*in, so its wo is *in, on the -y side.
    const auto out = bsdf::refract(*in, {0, -1, 0}, kGlass);
    ASSERT_TRUE(out.has_value()) << deg;
    EXPECT_NEAR(glm::length(*out - wo), 0.0, 1e-12) << deg;
  }
}

TEST(Bsdf, 04_TotalInternalReflectionBeyondTheCriticalAngle) {
  // From inside glass (eta = 1.5 / 1) the critical angle is asin(1/1.5) = 41.81 degrees.
  const double critical = std::asin(1.0 / kGlass) * 180.0 / kPi;
  EXPECT_NEAR(critical, 41.8103, 1e-4);
  EXPECT_TRUE(bsdf::refract(fromNormal(critical - 0.01), {0, 1, 0}, kGlass).has_value());
  EXPECT_FALSE(bsdf::refract(fromNormal(critical + 0.01), {0, 1, 0}, kGlass).has_value());
  EXPECT_FALSE(bsdf::refract(fromNormal(60.0), {0, 1, 0}, kGlass).has_value());
  // Just below the critical angle the transmitted ray grazes the surface (90 degrees).
  const auto grazing = bsdf::refract(fromNormal(critical - 1e-6), {0, 1, 0}, kGlass);
  ASSERT_TRUE(grazing.has_value());
  EXPECT_NEAR(angleDegrees(*grazing, {0, -1, 0}), 90.0, 0.05);
  // Fresnel is 1 past the critical angle and below 1 before it.
  EXPECT_EQ(bsdf::fresnelDielectric(std::cos(radians(critical + 0.01)), kGlass), 1.0);
  EXPECT_LT(bsdf::fresnelDielectric(std::cos(radians(critical - 0.5)), kGlass), 1.0);
}

TEST(Bsdf, 05_FresnelHandValues) {
  // Normal incidence: ((n - 1) / (n + 1))^2 = (0.5 / 2.5)^2 = 0.04, from either side.
  EXPECT_NEAR(bsdf::fresnelDielectric(1.0, 1.0 / kGlass), 0.04, 1e-15);
  EXPECT_NEAR(bsdf::fresnelDielectric(1.0, kGlass), 0.04, 1e-15);
  // Water (1.333): ((0.333) / (2.333))^2 = 0.02037.
  EXPECT_NEAR(bsdf::fresnelDielectric(1.0, 1.0 / 1.333), 0.0203737, 1e-6);
  // Grazing incidence reflects everything.
  EXPECT_NEAR(bsdf::fresnelDielectric(0.0, 1.0 / kGlass), 1.0, 1e-15);
  EXPECT_NEAR(bsdf::fresnelDielectric(1e-4, 1.0 / kGlass), 1.0, 1e-3);
  // 45 degrees into glass: R = 0.0502399 (Rs = 0.0920133, Rp = Rs^2 = 0.0084664, Abeles).
  EXPECT_NEAR(bsdf::fresnelDielectric(std::cos(radians(45.0)), 1.0 / kGlass), 0.0502399, 1e-7);
  // Brewster's angle atan(1.5) = 56.31 degrees: Rp = 0 and Rs = sin^2(theta_i - theta_t) =
  // (5/13)^2, so R = Rs / 2 = 25/338 = 0.0739645.
  EXPECT_NEAR(bsdf::fresnelDielectric(std::cos(std::atan(kGlass)), 1.0 / kGlass), 25.0 / 338.0,
              1e-7);
  // Any angle, either side: the textbook formula with n1, n2 written out.
  for (double deg = 0.0; deg < 90.0; deg += 2.5) {
    const double c = std::cos(radians(deg));
    EXPECT_NEAR(bsdf::fresnelDielectric(c, 1.0 / kGlass),
                fresnelTextbook(radians(deg), 1.0, kGlass), 1e-14)
        << deg;
    EXPECT_NEAR(bsdf::fresnelDielectric(c, kGlass), fresnelTextbook(radians(deg), kGlass, 1.0),
                1e-14)
        << deg;
  }
  // Reflectance grows monotonically towards grazing from outside.
  double previous = 0.0;
  for (double deg = 0.0; deg <= 90.0; deg += 1.0) {
    const double r = bsdf::fresnelDielectric(std::cos(radians(deg)), 1.0 / kGlass);
    EXPECT_GE(r, previous - 1e-15) << deg;
    previous = r;
  }
}

TEST(Bsdf, 06_DielectricLobesConserveEnergy) {
  // Clear glass: R + T = 1 at every angle, from outside and from inside; past the
  // critical angle a single reflection of weight 1.
  Material glass = material(MaterialType::Dielectric);
  glass.colour = Vec3(1.0);
  glass.ior = kGlass;
  for (double deg = 0.0; deg < 90.0; deg += 1.0) {
    for (bool outside : {true, false}) {
      const Vec3 wo = fromNormal(deg);
      // From inside, the outward normal points away from wo.
      const SurfaceInteraction si = hitAt(outside ? Vec3(0, 1, 0) : Vec3(0, -1, 0), wo);
      ASSERT_EQ(si.frontFace, outside);
      const SpecularLobes lobes = bsdf::specularLobes(glass, si, wo);
      ASSERT_GE(lobes.count, 1);
      Vec3 sum(0.0);
      for (int i = 0; i < lobes.count; ++i) sum += lobes.lobe[i].weight;
      EXPECT_NEAR(sum.x, 1.0, 1e-14) << deg << (outside ? " outside" : " inside");
      EXPECT_NEAR(sum.y, 1.0, 1e-14);
      const double r =
          bsdf::fresnelDielectric(std::cos(radians(deg)), outside ? 1.0 / kGlass : kGlass);
      EXPECT_NEAR(lobes.lobe[0].weight.x, r, 1e-14);
      EXPECT_EQ(lobes.lobe[0].kind, RayKind::Reflection);
      const bool tir = !outside && deg > 41.81;
      EXPECT_EQ(lobes.count, tir ? 1 : 2) << deg;
      if (!tir) {
        EXPECT_EQ(lobes.lobe[1].kind, RayKind::Refraction);
      }
      for (int i = 0; i < lobes.count; ++i) {
        EXPECT_TRUE(lobes.lobe[i].specular);
        EXPECT_EQ(lobes.lobe[i].pdf, 0.0);
      }
    }
  }
}

TEST(Bsdf, 07_DielectricDirectionsFromBothSides) {
  Material glass = material(MaterialType::Dielectric);
  glass.colour = Vec3(1.0);
  glass.ior = kGlass;
  // Entering at 45 degrees: mirror to the other side of the normal, refract to 28.13
  // degrees below the surface.
  const Vec3 wo = fromNormal(45.0);
  const SpecularLobes in = bsdf::specularLobes(glass, hitAt({0, 1, 0}, wo), wo);
  ASSERT_EQ(in.count, 2);
  EXPECT_NEAR(glm::length(in.lobe[0].wi - glm::normalize(Vec3(1, 1, 0))), 0.0, 1e-15);
  EXPECT_NEAR(angleDegrees(in.lobe[1].wi, {0, -1, 0}), 28.1255057, 1e-6);
  // Leaving at 20 degrees (the outward normal is +y and wo is below the surface): the ray
  // exits at asin(1.5 sin 20) = asin(0.5130302) = 30.8658825 degrees.
  const Vec3 woInside = -fromNormal(20.0);
  const SurfaceInteraction si = hitAt({0, 1, 0}, woInside);
  ASSERT_FALSE(si.frontFace);
  const SpecularLobes out = bsdf::specularLobes(glass, si, woInside);
  ASSERT_EQ(out.count, 2);
  EXPECT_LT(out.lobe[0].wi.y, 0.0);  // reflection stays inside
  EXPECT_NEAR(angleDegrees(out.lobe[1].wi, {0, 1, 0}), 30.8658825, 1e-6);
  EXPECT_NEAR(out.lobe[0].weight.x, bsdf::fresnelDielectric(std::cos(radians(20.0)), kGlass),
              1e-15);
}

TEST(Bsdf, 08_MirrorUsesTheSeedRates) {
  Material mirror = material(MaterialType::Mirror);
  mirror.colour = Vec3(1.0, 0.5, 0.25);
  mirror.reflectionRate = 0.3;
  mirror.refractionRate = 0.6;
  mirror.ior = kGlass;
  // Outside: reflection 0.3 colour, refraction 0.6 colour through ior 1.5.
  const Vec3 wo = fromNormal(45.0);
  const SpecularLobes a = bsdf::specularLobes(mirror, hitAt({0, 1, 0}, wo), wo);
  ASSERT_EQ(a.count, 2);
  EXPECT_NEAR(glm::length(a.lobe[0].weight - Vec3(0.3, 0.15, 0.075)), 0.0, 1e-15);
  EXPECT_NEAR(glm::length(a.lobe[1].weight - Vec3(0.6, 0.3, 0.15)), 0.0, 1e-15);
  EXPECT_NEAR(angleDegrees(a.lobe[1].wi, {0, -1, 0}), 28.1255057, 1e-6);
  // Inside past the critical angle: the refraction's 0.6 joins the reflection's 0.3.
  const Vec3 woInside = -fromNormal(60.0);
  const SpecularLobes b = bsdf::specularLobes(mirror, hitAt({0, 1, 0}, woInside), woInside);
  ASSERT_EQ(b.count, 1);
  EXPECT_EQ(b.lobe[0].kind, RayKind::Reflection);
  EXPECT_NEAR(glm::length(b.lobe[0].weight - Vec3(0.9, 0.45, 0.225)), 0.0, 1e-15);
  // The default pure mirror: one reflection of weight colour, no refraction ray.
  Material pure = material(MaterialType::Mirror);
  const SpecularLobes c = bsdf::specularLobes(pure, hitAt({0, 1, 0}, wo), wo);
  ASSERT_EQ(c.count, 1);
  EXPECT_EQ(c.lobe[0].weight, Vec3(0.8));
  // Non-specular materials have no specular lobes, specular ones no eval or pdf.
  EXPECT_EQ(bsdf::specularLobes(material(MaterialType::Diffuse), hitAt({0, 1, 0}, wo), wo).count,
            0);
  EXPECT_EQ(bsdf::eval(mirror, hitAt({0, 1, 0}, wo), wo, a.lobe[0].wi), Vec3(0.0));
  EXPECT_EQ(bsdf::pdf(mirror, hitAt({0, 1, 0}, wo), wo, a.lobe[0].wi), 0.0);
}

TEST(Bsdf, 09_SpecularSamplingPicksLobesByLuminance) {
  // Glass at 70 degrees: R = 0.1753 (textbook), T = 0.8247. sample() picks reflection with
  // probability R and returns weight / probability = 1 either way, so the mean weight is
  // R + T = 1 exactly and the frequency of reflections estimates R.
  Material glass = material(MaterialType::Dielectric);
  glass.colour = Vec3(1.0);
  glass.ior = kGlass;
  const Vec3 wo = fromNormal(70.0);
  const SurfaceInteraction si = hitAt({0, 1, 0}, wo);
  const double r = fresnelTextbook(radians(70.0), 1.0, kGlass);
  Sampler sampler(3, 0, 0, 0);
  const int n = 200000;
  int reflections = 0;
  for (int i = 0; i < n; ++i) {
    const auto s = bsdf::sample(glass, si, wo, sampler);
    ASSERT_TRUE(s.has_value());
    EXPECT_TRUE(s->specular);
    EXPECT_NEAR(s->weight.x, 1.0, 1e-12);
    if (s->kind == RayKind::Reflection) ++reflections;
  }
  // Binomial standard deviation sqrt(n R (1 - R)) = 170; allow 5 of them.
  EXPECT_NEAR(reflections, n * r, 5.0 * std::sqrt(n * r * (1.0 - r)));
  // A tinted mirror of the original course program: weights 0.3 c and 0.6 c, so reflections
  // are picked a third of the time with weight 0.9 c, and the mean weight is the sum 0.9 c.
  Material mirror = material(MaterialType::Mirror);
  mirror.colour = Vec3(0.5, 1.0, 0.2);
  mirror.reflectionRate = 0.3;
  mirror.refractionRate = 0.6;
  Vec3 mean(0.0);
  for (int i = 0; i < n; ++i) mean += bsdf::sample(mirror, si, wo, sampler)->weight / double(n);
  EXPECT_NEAR(glm::length(bsdf::sample(mirror, si, wo, sampler)->weight - 0.9 * mirror.colour), 0.0,
              1e-12);
  EXPECT_NEAR(glm::length(mean - 0.9 * mirror.colour), 0.0, 1e-9);
  // A black mirror scatters nothing.
  mirror.colour = Vec3(0.0);
  EXPECT_FALSE(bsdf::sample(mirror, si, wo, sampler).has_value());
}

TEST(Bsdf, 10_DiffuseIsLambert) {
  Material d = material(MaterialType::Diffuse);
  d.colour = Vec3(0.2, 0.4, 0.6);
  const Vec3 wo = fromNormal(30.0);
  const SurfaceInteraction si = hitAt({0, 1, 0}, wo);
  // f cos = colour / pi * cos(60 degrees) for wi at 60 degrees from the normal.
  const Vec3 wi = -fromNormal(-60.0) * Vec3(1, -1, 1);
  EXPECT_NEAR(glm::dot(wi, Vec3(0, 1, 0)), 0.5, 1e-15);
  EXPECT_NEAR(glm::length(bsdf::eval(d, si, wo, wi) - d.colour / kPi * 0.5), 0.0, 1e-15);
  EXPECT_NEAR(bsdf::pdf(d, si, wo, wi), 0.5 / kPi, 1e-15);
  // Nothing below the surface.
  EXPECT_EQ(bsdf::eval(d, si, wo, {0, -1, 0}), Vec3(0.0));
  EXPECT_EQ(bsdf::pdf(d, si, wo, {0, -1, 0}), 0.0);
  // Hit from the back (frontFace false): the surface scatters on wo's side, below.
  const SurfaceInteraction back = hitAt({0, 1, 0}, -wo);
  EXPECT_NEAR(glm::length(bsdf::eval(d, back, -wo, -wi) - d.colour / kPi * 0.5), 0.0, 1e-15);
  EXPECT_EQ(bsdf::eval(d, back, -wo, wi), Vec3(0.0));
  // Samples: on wo's side, weight exactly the colour, pdf cos / pi.
  Sampler sampler(4, 0, 0, 0);
  for (int i = 0; i < 1000; ++i) {
    const auto s = bsdf::sample(d, back, -wo, sampler);
    ASSERT_TRUE(s.has_value());
    EXPECT_LT(s->wi.y, 0.0);
    EXPECT_EQ(s->weight, d.colour);
    EXPECT_NEAR(s->pdf, -s->wi.y / kPi, 1e-15);
    EXPECT_FALSE(s->specular);
    EXPECT_EQ(s->kind, RayKind::Diffuse);
  }
}

TEST(Bsdf, 11_EvalIsReciprocal) {
  // f(wo, wi) = f(wi, wo): eval(wo, wi) / cos(wi) == eval(wi, wo) / cos(wo), for Lambert
  // and for the modified Phong model (the mirror angle is symmetric).
  Sampler rng(5, 0, 0, 0);
  const Normal3 n = glm::normalize(Vec3(0.2, 1.0, -0.3));
  for (MaterialType type : {MaterialType::Diffuse, MaterialType::Glossy}) {
    for (double exponent : {1.0, 10.0, 100.0}) {
      Material m = material(type);
      m.colour = Vec3(0.7, 0.5, 0.3);
      m.exponent = exponent;
      m.specular = 0.6;
      for (int i = 0; i < 2000; ++i) {
        const Vec3 a = randomUpper(rng, n), b = randomUpper(rng, n);
        const Vec3 fab = bsdf::eval(m, hitAt(n, a), a, b) / glm::dot(b, n);
        const Vec3 fba = bsdf::eval(m, hitAt(n, b), b, a) / glm::dot(a, n);
        EXPECT_NEAR(glm::length(fab - fba), 0.0, 1e-12 * (1.0 + glm::length(fab)));
      }
    }
  }
}

TEST(Bsdf, 12_SampleWeightEqualsEvalOverPdf) {
  // For every sampled direction: pdf == pdf(wo, wi) and weight == eval(wo, wi) / pdf.
  Sampler rng(6, 0, 0, 0);
  const Normal3 n = glm::normalize(Vec3(-0.4, 0.1, 1.0));
  for (MaterialType type : {MaterialType::Diffuse, MaterialType::Glossy}) {
    for (double exponent : {1.0, 20.0, 500.0}) {
      for (double spec : {0.0, 0.4, 1.0}) {
        Material m = material(type);
        m.colour = Vec3(0.9, 0.3, 0.6);
        m.exponent = exponent;
        m.specular = spec;
        for (int i = 0; i < 2000; ++i) {
          const Vec3 wo = randomUpper(rng, n);
          const SurfaceInteraction si = hitAt(n, wo);
          const auto s = bsdf::sample(m, si, wo, rng);
          if (!s) continue;
          EXPECT_GT(glm::dot(s->wi, n), 0.0);
          EXPECT_NEAR(glm::length(s->wi), 1.0, 1e-12);
          const double p = bsdf::pdf(m, si, wo, s->wi);
          EXPECT_NEAR(s->pdf, p, 1e-12 * p);
          const Vec3 expected = bsdf::eval(m, si, wo, s->wi) / p;
          EXPECT_NEAR(glm::length(s->weight - expected), 0.0,
                      1e-12 * (1.0 + glm::length(expected)));
        }
      }
    }
  }
}

TEST(Bsdf, 13_GlossyAlbedoAtNormalIncidence) {
  // Modified Phong at normal incidence: the lobe's albedo is
  // ks (n + 2) / (2 pi) * integral of cos^(n+1) = ks exactly; the diffuse part adds
  // (1 - ks) colour. With ks = 0.5 and colour 0.6 the albedo is 0.5 + 0.3 = 0.8.
  // Estimated as the mean sample weight over 4 * 10^5 samples, within 5 standard errors.
  for (double exponent : {1.0, 10.0, 100.0}) {
    Material m = material(MaterialType::Glossy);
    m.colour = Vec3(0.6);
    m.specular = 0.5;
    m.exponent = exponent;
    const Vec3 wo(0, 0, 1);
    const SurfaceInteraction si = hitAt({0, 0, 1}, wo);
    Sampler sampler(7, 0, 0, 0);
    const int count = 400000;
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < count; ++i) {
      const auto s = bsdf::sample(m, si, wo, sampler);
      const double w = s ? s->weight.x : 0.0;
      sum += w;
      sum2 += w * w;
    }
    const double mean = sum / count;
    const double se = std::sqrt((sum2 / count - mean * mean) / count);
    EXPECT_NEAR(mean, 0.8, 5.0 * se + 1e-12) << "exponent " << exponent;
    // Oblique incidence loses lobe energy under the horizon: albedo below 0.8.
    const Vec3 woGrazing = glm::normalize(Vec3(1, 0, 0.2));
    const SurfaceInteraction sg = hitAt({0, 0, 1}, woGrazing);
    double sumG = 0.0;
    for (int i = 0; i < count; ++i) {
      const auto s = bsdf::sample(m, sg, woGrazing, sampler);
      if (s) {
        EXPECT_GT(s->wi.z, 0.0);
        sumG += s->weight.x;
      }
    }
    EXPECT_LT(sumG / count, 0.8);
  }
}

TEST(Bsdf, 14_GlossyRejectsDirectionsUnderTheSurface) {
  // At grazing incidence part of a wide lobe points below the surface: those samples are
  // rejected (nothing returned) and pdf() is zero there; nothing below leaks out.
  Material m = material(MaterialType::Glossy);
  m.specular = 1.0;
  m.exponent = 1.0;
  const Vec3 wo = glm::normalize(Vec3(-1, 0, 0.1));
  const SurfaceInteraction si = hitAt({0, 0, 1}, wo);
  Sampler sampler(8, 0, 0, 0);
  int rejected = 0;
  for (int i = 0; i < 10000; ++i) {
    const auto s = bsdf::sample(m, si, wo, sampler);
    if (!s) {
      ++rejected;
      continue;
    }
    EXPECT_GT(s->wi.z, 0.0);
    EXPECT_EQ(s->kind, RayKind::Glossy);
  }
  // About half of the n = 1 lobe around a mirror direction 5.7 degrees above the horizon
  // lies below it.
  EXPECT_GT(rejected, 3500);
  EXPECT_LT(rejected, 5000);
  EXPECT_EQ(bsdf::pdf(m, si, wo, glm::normalize(Vec3(1, 0, -0.1))), 0.0);
  EXPECT_EQ(bsdf::eval(m, si, wo, glm::normalize(Vec3(1, 0, -0.1))), Vec3(0.0));
  // A black glossy surface with no lobe scatters nothing.
  m.specular = 0.0;
  m.colour = Vec3(0.0);
  EXPECT_FALSE(bsdf::sample(m, si, wo, sampler).has_value());
}

TEST(Bsdf, 15_RatesWeighedByFresnelAtThreeAngles) {
  // A Phong (or mirror) surface of glass, n = 1.5 seen from air (eta = 1 / 1.5), with the
  // option "fresnel": the reflected ray gets kr R and the refracted one kt (1 - R) (The
  // Ray Tracer Challenge, ch. 11). R by the published formulas, computed by hand:
  //   normal incidence, both models: R0 = ((1.5 - 1) / (1.5 + 1))^2 = 0.25^2 = 0.04.
  //   Exact (Hecht 4.34), R = (R_s + R_p) / 2 with sin t = sin i / 1.5:
  //     45 deg: cos i = 0.7071068, cos t = sqrt(1 - 0.5 / 2.25) = 0.8819171;
  //       R_s = ((0.7071068 - 1.5 * 0.8819171) / (0.7071068 + 1.3228757))^2 = 0.0920134,
  //       R_p = ((1.5 * 0.7071068 - 0.8819171) / (1.0606602 + 0.8819171))^2 = 0.0084665,
  //       R = 0.0502399.
  //     80 deg: cos i = 0.1736482, cos t = sqrt(1 - 0.9698463 / 2.25) = 0.7542925;
  //       R_s = ((0.1736482 - 1.1314388) / (0.1736482 + 1.1314388))^2 = 0.5385949,
  //       R_p = ((0.2604723 - 0.7542925) / (0.2604723 + 0.7542925))^2 = 0.2368138,
  //       R = 0.3877044.
  //   Schlick, R = R0 + (1 - R0)(1 - cos i)^5:
  //     45 deg: (1 - 0.7071068)^5 = 0.0021555, R = 0.04 + 0.96 * 0.0021555 = 0.0420693;
  //     80 deg: (1 - 0.1736482)^5 = 0.3853230, R = 0.04 + 0.96 * 0.3853230 = 0.4099101.
  struct Case {
    FresnelModel model;
    double degrees, R;
  };
  const Case cases[] = {
      {FresnelModel::Exact, 0.0, 0.04},         {FresnelModel::Exact, 45.0, 0.0502399},
      {FresnelModel::Exact, 80.0, 0.3877044},   {FresnelModel::Schlick, 0.0, 0.04},
      {FresnelModel::Schlick, 45.0, 0.0420693}, {FresnelModel::Schlick, 80.0, 0.4099101}};
  for (MaterialType type : {MaterialType::Phong, MaterialType::BlinnPhong, MaterialType::Mirror})
    for (const Case& c : cases) {
      SCOPED_TRACE(std::string(toString(type)) + " " + toString(c.model) + " at " +
                   std::to_string(c.degrees));
      Material m = material(type);
      m.colour = Vec3(1.0);
      m.ior = kGlass;
      m.reflectionRate = 0.5;
      m.refractionRate = 0.9;  // kr + kt may pass 1 with Fresnel: kr R + kt (1 - R) <= 0.9
      m.rateFresnel = c.model;
      // Seen from above the normal +y (entering), tilted by the angle.
      const Vec3 wo = fromNormal(c.degrees);
      const SpecularLobes lobes = bsdf::specularLobes(m, hitAt({0, 1, 0}, wo), wo);
      ASSERT_EQ(lobes.count, 2);
      EXPECT_EQ(lobes.lobe[0].kind, RayKind::Reflection);
      EXPECT_NEAR(lobes.lobe[0].weight.x, 0.5 * c.R, 1e-7);
      EXPECT_EQ(lobes.lobe[1].kind, RayKind::Refraction);
      EXPECT_NEAR(lobes.lobe[1].weight.x, 0.9 * (1.0 - c.R), 1e-7);
    }
  // Without the option the rates stay constant; with it, total internal reflection (from
  // inside at 60 degrees, past the critical angle 41.8) sends R = 1 of kr back and nothing
  // of kt (without it, Whitted's rule reflects kt too).
  Material m = material(MaterialType::Phong);
  m.ior = kGlass;
  m.reflectionRate = 0.3;
  m.refractionRate = 0.6;
  const Vec3 wo = fromNormal(80.0);
  const SpecularLobes plain = bsdf::specularLobes(m, hitAt({0, 1, 0}, wo), wo);
  ASSERT_EQ(plain.count, 2);
  EXPECT_EQ(plain.lobe[0].weight, Vec3(0.3));
  EXPECT_EQ(plain.lobe[1].weight, Vec3(0.6));
  const Vec3 inside = -fromNormal(60.0);
  const SpecularLobes tirPlain = bsdf::specularLobes(m, hitAt({0, 1, 0}, inside), inside);
  ASSERT_EQ(tirPlain.count, 1);
  EXPECT_NEAR(tirPlain.lobe[0].weight.x, 0.9, 1e-15);
  m.rateFresnel = FresnelModel::Schlick;
  const SpecularLobes tir = bsdf::specularLobes(m, hitAt({0, 1, 0}, inside), inside);
  ASSERT_EQ(tir.count, 1);
  EXPECT_EQ(tir.lobe[0].kind, RayKind::Reflection);
  EXPECT_NEAR(tir.lobe[0].weight.x, 0.3, 1e-15);
}

TEST(Bsdf, 16_PhongSamplingCarriesTheFresnelShareOnAverage) {
  // Path tracing picks one of a Phong material's parts; with Fresnel the picked delta ray
  // carries R or 1 - R of its rate, so the mean weight of reflected samples equals the
  // scaled kr R and of refracted ones kt (1 - R): scale = 1 / max(1, kd + ks + kr + kt)
  // = 1 / 1.5 here, R = 0.0420693 at 45 degrees (Schlick, Bsdf.15), so the expected sums
  // per sample are 0.5 / 1.5 * 0.0420693 = 0.0140231 and 0.5 / 1.5 * 0.9579307 = 0.3193102.
  Material m = material(MaterialType::Phong);
  m.ior = kGlass;
  m.diffuse = 0.5;
  m.specular = 0.0;
  m.reflectionRate = 0.5;
  m.refractionRate = 0.5;
  m.rateFresnel = FresnelModel::Schlick;
  const Vec3 wo = fromNormal(45.0);
  const SurfaceInteraction si = hitAt({0, 1, 0}, wo);
  Sampler rng(37, 0, 0, 0);
  const int n = 200000;
  double reflected = 0.0, refracted = 0.0;
  for (int i = 0; i < n; ++i) {
    const auto s = bsdf::sample(m, si, wo, rng);
    if (!s || !s->specular) continue;
    (s->kind == RayKind::Reflection ? reflected : refracted) += s->weight.x;
  }
  // Each delta part is picked with probability 0.5 / 1.4 (its share of kd lum(colour) + kr
  // + kt = 0.4 + 0.5 + 0.5) and has a fixed weight: binomial noise only (5 sigma).
  EXPECT_NEAR(reflected / n, 0.0140231, 6e-4);
  EXPECT_NEAR(refracted / n, 0.3193102, 6e-3);
}

}  // namespace
}  // namespace raylab
