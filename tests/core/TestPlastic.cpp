// The plastic material (materials/PlasticBsdf.h): a GGX or Beckmann coating over a
// Lambertian base. Energy (the white furnace), the smooth limit (the coating's albedo is
// Fresnel's reflectance), reciprocity, sampled weights equal to eval / pdf, and the lobe
// each sampled ray records in the ray trees of the four algorithms. The sampler's
// chi-square test is Chi2.16.
#include "raylab/core/Bsdf.h"
#include "raylab/core/Fresnel.h"
#include "raylab/core/Sampler.h"
#include "raylab/core/Sampling.h"

#include "TransportScenes.h"
#include "materials/PlasticBsdf.h"
#include "raylab/core/Tracer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <set>

namespace raylab {
namespace {

using testing::addMaterial;
using testing::addObject;
using testing::makeMaterial;

Vec3 spherical(double thetaDegrees, double phi = 0.3) {
  const double t = radians(thetaDegrees);
  return {std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi), std::cos(t)};
}

SurfaceInteraction flatHit(const Vec3& wo) {
  SurfaceInteraction si;
  si.n = Normal3(0.0, 0.0, 1.0);
  si.frontFace = wo.z > 0.0;
  return si;
}

Material plastic(const Vec3& colour, MicrofacetModel model, double alpha, double ior = 1.5,
                 bool visible = true) {
  Material m;
  m.type = MaterialType::Plastic;
  m.colour = colour;
  m.distribution = model;
  m.roughness = alpha;
  m.ior = ior;
  m.visibleNormals = visible;
  return m;
}

/// Mean sampled weight (the directional albedo) and its standard error.
std::pair<double, double> albedo(const Material& m, const Vec3& wo, int n, std::uint64_t seed) {
  const SurfaceInteraction si = flatHit(wo);
  Sampler rng(seed, 0, 0, 0);
  double sum = 0.0, sum2 = 0.0;
  for (int i = 0; i < n; ++i) {
    const auto s = bsdf::sample(m, si, wo, rng);
    const double w = s ? s->weight.y : 0.0;
    sum += w;
    sum2 += w * w;
  }
  const double mean = sum / n;
  return {mean, std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n)};
}

TEST(Plastic, 01_WhiteFurnaceReflectsEverythingAndNeverMore) {
  // A white base under any coating reflects all the light: the coating reflects E(theta_o)
  // and the base the rest, 1 - E (Kelemen and Szirmay-Kalos 2001). A grey base (0.5)
  // reflects E + 0.5 (1 - E) < 1. Estimated by sampling (the mean weight), 40k samples,
  // for GGX and Beckmann, alpha from near-mirror to very rough, at 0, 45 and 80 degrees,
  // with both normal samplers; the tabulated E allows a few 1e-3.
  for (MicrofacetModel model : {MicrofacetModel::GGX, MicrofacetModel::Beckmann})
    for (double alpha : {0.02, 0.2, 0.6, 1.0})
      for (double degrees : {0.0, 45.0, 80.0})
        for (bool visible : {true, false}) {
          if (model == MicrofacetModel::Beckmann && !visible) continue;
          const Vec3 wo = spherical(degrees);
          const Material white = plastic(Vec3(1.0), model, alpha, 1.5, visible);
          const auto [E, se] = albedo(white, wo, 40000, 7 + int(degrees));
          std::printf("  white plastic %-8s alpha %.2f at %2.0f deg%s: albedo %.4f +- %.4f\n",
                      toString(model), alpha, degrees, visible ? "" : " (D cos)", E, se);
          EXPECT_NEAR(E, 1.0, 5.0 * se + 4e-3) << toString(model) << " " << alpha << " " << degrees;
          const Material grey = plastic(Vec3(0.5), model, alpha, 1.5, visible);
          const auto [G, seG] = albedo(grey, wo, 20000, 9 + int(degrees));
          const double coat = bsdf::plastic::coatingAlbedo(grey, wo.z);
          EXPECT_NEAR(G, coat + 0.5 * (1.0 - coat), 5.0 * seG + 4e-3);
          EXPECT_LT(G, 1.0);
        }
}

TEST(Plastic, 02_ASmoothCoatingReflectsFresnelsShare) {
  // As alpha -> 0 the coating is a smooth interface: its albedo is the Fresnel reflectance
  // of n = 1.5 from air, 0.04 at normal incidence ((0.5 / 2.5)^2) and 0.0891867 at 60
  // degrees (Hecht 4.34: cos t = sqrt(1 - 0.75 / 2.25) = 0.8164966, R_s = ((0.5 - 1.2247449)
  // / (0.5 + 1.2247449))^2 = 0.1765395, R_p = ((0.75 - 0.8164966) / (0.75 + 0.8164966))^2 =
  // 0.0018017, R = 0.0891706 ... with the exact cosines 0.0891867).
  const Material m = plastic(Vec3(0.5), MicrofacetModel::GGX, 0.001);
  EXPECT_NEAR(bsdf::plastic::coatingAlbedo(m, 1.0), 0.04, 1e-3);
  EXPECT_NEAR(bsdf::plastic::coatingAlbedo(m, 0.5), fresnel::dielectric(0.5, 1.0 / 1.5), 2e-3);
  EXPECT_NEAR(bsdf::plastic::coatingAlbedo(m, 0.5), 0.0891867, 2e-3);
  // Rougher coatings lose some of it to masking at grazing angles, never gain beyond 1.
  const Material rough = plastic(Vec3(0.5), MicrofacetModel::GGX, 0.5);
  EXPECT_LT(bsdf::plastic::coatingAlbedo(rough, 0.1), bsdf::plastic::coatingAlbedo(m, 0.1));
}

TEST(Plastic, 03_EvalIsReciprocalAndSplitsIntoCoatingAndBase) {
  // f(wo, wi) = f(wi, wo) (both parts are symmetric), and eval = coating + base.
  Sampler rng(3, 0, 0, 0);
  for (MicrofacetModel model : {MicrofacetModel::GGX, MicrofacetModel::Beckmann}) {
    const Material m = plastic(Vec3(0.7, 0.4, 0.2), model, 0.3);
    for (int i = 0; i < 200; ++i) {
      const Vec3 a = sampleCosineHemisphere(rng.next2D());
      const Vec3 b = sampleCosineHemisphere(rng.next2D());
      const Vec3 fab = bsdf::eval(m, flatHit(a), a, b) / b.z;
      const Vec3 fba = bsdf::eval(m, flatHit(b), b, a) / a.z;
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(fab[c], fba[c], 1e-10 * std::max(1.0, fab[c]));
      const Vec3 parts = bsdf::plastic::evalCoating(m, flatHit(a), a, b) +
                         bsdf::plastic::evalBase(m, flatHit(a), a, b);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(parts[c], fab[c] * b.z, 1e-12);
    }
  }
}

TEST(Plastic, 04_SamplesWeighEvalOverPdfAndNameTheirLobe) {
  // Every sample's weight is eval / pdf at its direction; a coating sample is a Glossy ray
  // and a base sample a Diffuse one, in the proportion E : lum(colour) (1 - E). The
  // coating rays of distributed tracing weigh evalCoating / their own density.
  const Material m = plastic(Vec3(0.6), MicrofacetModel::GGX, 0.25);
  const Vec3 wo = spherical(50.0);
  const SurfaceInteraction si = flatHit(wo);
  Sampler rng(4, 0, 0, 0);
  int glossy = 0, diffuse = 0;
  for (int i = 0; i < 20000; ++i) {
    const auto s = bsdf::sample(m, si, wo, rng);
    if (!s) continue;
    EXPECT_FALSE(s->specular);
    (s->kind == RayKind::Glossy ? glossy : diffuse) += 1;
    EXPECT_TRUE(s->kind == RayKind::Glossy || s->kind == RayKind::Diffuse);
    const Vec3 expected = bsdf::eval(m, si, wo, s->wi) / bsdf::pdf(m, si, wo, s->wi);
    EXPECT_NEAR(s->weight.x, expected.x, 1e-9 * std::max(1.0, expected.x));
    EXPECT_NEAR(s->pdf, bsdf::pdf(m, si, wo, s->wi), 1e-9 * s->pdf);
  }
  const double E = bsdf::plastic::coatingAlbedo(m, wo.z);
  const double pCoat = E / (E + 0.6 * (1.0 - E));
  const double n = glossy + diffuse;
  EXPECT_NEAR(glossy / n, pCoat, 5.0 * std::sqrt(pCoat * (1.0 - pCoat) / n));
  for (int i = 0; i < 2000; ++i) {
    const auto s = bsdf::plastic::sampleCoating(m, si, wo, rng);
    if (!s) continue;
    EXPECT_EQ(s->kind, RayKind::Glossy);
    const double expected = bsdf::plastic::evalCoating(m, si, wo, s->wi).x / s->pdf;
    EXPECT_NEAR(s->weight.x, expected, 1e-9 * std::max(1.0, expected));
  }
}

/// A plastic ball on a diffuse floor under a small area light and a point light.
Scene plasticScene() {
  Scene scene;
  const int floor = addMaterial(scene, makeMaterial("floor", MaterialType::Diffuse, Vec3(0.5)));
  const int lamp =
      addMaterial(scene, makeMaterial("lamp", MaterialType::Diffuse, Vec3(0.0), Vec3(20.0)));
  Material p = makeMaterial("plastic", MaterialType::Plastic, Vec3(0.8, 0.2, 0.2));
  p.roughness = 0.2;
  const int ball = addMaterial(scene, p);
  addObject(scene, "floor",
            std::make_unique<Quad>(Point3(-5, -1, 5), Vec3(10, 0, 0), Vec3(0, 0, -10)), floor);
  addObject(scene, "lamp",
            std::make_unique<Quad>(Point3(-0.5, 3, -0.5), Vec3(1, 0, 0), Vec3(0, 0, 1)), lamp);
  addObject(scene, "ball", std::make_unique<Sphere>(Point3(0, 0, 0), 1.0), ball);
  scene.pointLights.push_back({"bulb", Point3(2, 3, 2), Vec3(5.0)});
  scene.camera.position = Point3(0, 0.5, 5);
  scene.camera.lookAt = Point3(0, 0, 0);
  scene.camera.width = 16;
  scene.camera.height = 16;
  return scene;
}

TEST(Plastic, 05_EachAlgorithmTreatsItsLobesAsItShould) {
  // The centre pixel hits the ball. Ray casting and Whitted: local shading only (shadow
  // rays, each weighted by the whole model). Distributed: shadow rays and Glossy rays
  // drawn from the coating (glossySamples of them), no Diffuse ray. Path tracing: one
  // continuation per bounce, Glossy or Diffuse by the lobe sampled; over 64 samples both
  // appear.
  const Scene scene = plasticScene();
  const int ball = scene.findObject("ball");
  for (Algorithm algorithm : {Algorithm::RayCasting, Algorithm::Whitted, Algorithm::Distributed,
                              Algorithm::PathTracing}) {
    SCOPED_TRACE(toString(algorithm));
    RenderSettings settings = scene.render;
    settings.algorithm = algorithm;
    settings.glossySamples = 3;
    const Tracer tracer(scene, settings);
    std::set<RayKind> kinds;
    for (int sample = 0; sample < 64; ++sample) {
      Stepper stepper(tracer, 8, 8, sample);
      stepper.runToEnd();
      const RayTree& tree = stepper.tree();
      ASSERT_EQ(tree.segments[0].object, ball);
      for (const RaySegment& s : tree.segments)
        if (s.parent == 0) kinds.insert(s.kind);
    }
    const bool shadow = kinds.count(RayKind::Shadow) > 0;
    const bool glossy = kinds.count(RayKind::Glossy) > 0;
    const bool diffuse = kinds.count(RayKind::Diffuse) > 0;
    EXPECT_TRUE(shadow);
    if (algorithm == Algorithm::RayCasting || algorithm == Algorithm::Whitted) {
      EXPECT_FALSE(glossy);
      EXPECT_FALSE(diffuse);
    } else if (algorithm == Algorithm::Distributed) {
      EXPECT_TRUE(glossy);
      EXPECT_FALSE(diffuse);
    } else {
      EXPECT_TRUE(glossy);
      EXPECT_TRUE(diffuse);
    }
  }
}

TEST(Plastic, 06_ThePointLitHighlightIsTheModelTimesTheLight) {
  // Ray casting's shadow ray to the point light carries f cos = bsdf::eval at the hit
  // (coating + base), and delivers I / d^2 (Whitted's local shading of microfacet models).
  const Scene scene = plasticScene();
  RenderSettings settings = scene.render;
  settings.algorithm = Algorithm::RayCasting;
  const Tracer tracer(scene, settings);
  Stepper stepper(tracer, 8, 8, 0);
  stepper.runToEnd();
  const RayTree& tree = stepper.tree();
  const RaySegment& camera = tree.segments[0];
  const Material& m =
      scene.materials[std::size_t(scene.objects[std::size_t(camera.object)].material)];
  SurfaceInteraction si;
  si.p = camera.endPoint;
  si.n = camera.normal;
  si.frontFace = true;
  bool found = false;
  for (const RaySegment& s : tree.segments) {
    if (s.parent != 0 || s.pointLight != 0) continue;
    found = true;
    const Vec3 f = bsdf::eval(m, si, -camera.direction, s.direction);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(s.weight[c], f[c], 1e-9);
  }
  EXPECT_TRUE(found);
}

}  // namespace
}  // namespace raylab
