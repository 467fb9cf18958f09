// The textbook shading models against hand-computed numbers: the classic Phong and
// Blinn-Phong reflection model (ClassicShading.h) at one point and through ray casting,
// Whitted and distributed tracing; the Fresnel equations with both polarisations and
// Schlick's approximation (Fresnel.h); the scene format of the new materials. Each expected
// value is derived in the comment beside it.
#include "TransportScenes.h"
#include "raylab/core/Box.h"
#include "raylab/core/Bsdf.h"
#include "raylab/core/ClassicShading.h"
#include "raylab/core/Fresnel.h"
#include "raylab/core/Quad.h"
#include "raylab/core/SceneIO.h"
#include "raylab/core/Sphere.h"
#include "raylab/core/Tracer.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace raylab {
namespace {

using testing::addMaterial;
using testing::addObject;
using ::testing::HasSubstr;
using testing::makeMaterial;
using testing::settingsFor;

/// The unit direction at `degrees` from the normal +y in the x-y plane, on the -x side for
/// positive angles.
Vec3 atAngle(double degrees) {
  const double a = radians(degrees);
  return {-std::sin(a), std::cos(a), 0.0};
}

const Normal3 kUp(0.0, 1.0, 0.0);

Material classicMaterial(MaterialType type) {
  Material m = makeMaterial("paint", type, Vec3(1.0, 0.5, 0.25));
  m.diffuse = 0.7;
  m.specular = 0.3;
  m.exponent = 10.0;
  m.reflectionRate = 0.0;
  return m;
}

TEST(ClassicShading, 01_PhongHighlightByHand) {
  // Light at 45 degrees on one side, viewer at 30 degrees on the other, in one plane: the
  // mirror direction R of L is at 45 degrees on the viewer's side, 15 degrees from V, so
  // (R.V)^10 = cos(15 deg)^10 = 0.9659258^10 = 0.7070299.
  const Vec3 L = atAngle(45.0), V = atAngle(-30.0);
  EXPECT_NEAR(classic::phongHighlight(kUp, V, L, 10.0), 0.7070299011541948, 1e-13);
  // Blinn: H is halfway between L and V, at (45 - 30) / 2 = 7.5 degrees from N, so
  // (N.H)^10 = cos(7.5 deg)^10 = 0.9176682.
  EXPECT_NEAR(classic::blinnPhongHighlight(kUp, V, L, 10.0), 0.917668156588543, 1e-13);
  // In the plane of incidence the half vector's angle to N is half the angle between R and
  // V, so Blinn with exponent 4n matches Phong with n to first order and cos(7.5)^40 =
  // cos(15)^10 (1 + O(angle^4)): 0.7091 against 0.7070.
  EXPECT_NEAR(classic::blinnPhongHighlight(kUp, V, L, 40.0), std::pow(std::cos(radians(7.5)), 40.0),
              1e-13);
  EXPECT_NEAR(classic::blinnPhongHighlight(kUp, V, L, 40.0), 0.7070299, 0.003);
  // The viewer exactly in the mirror direction: both highlights are 1 for any n.
  EXPECT_NEAR(classic::phongHighlight(kUp, atAngle(-45.0), L, 1000.0), 1.0, 1e-12);
  EXPECT_NEAR(classic::blinnPhongHighlight(kUp, atAngle(-45.0), L, 1000.0), 1.0, 1e-12);
  // R.V < 0 (viewer at 60 degrees on the light's side, 130 degrees from R): no highlight, not a
  // negative one.
  EXPECT_EQ(classic::phongHighlight(kUp, atAngle(60.0), atAngle(70.0), 3.0), 0.0);
  // A light below the surface gives no highlight even where R.V > 0.
  EXPECT_EQ(classic::phongHighlight(kUp, V, Vec3(0.6, -0.8, 0.0), 10.0), 0.0);
  EXPECT_EQ(classic::blinnPhongHighlight(kUp, V, Vec3(0.6, -0.8, 0.0), 10.0), 0.0);
}

TEST(ClassicShading, 02_OneLightByHand) {
  // kd = 0.7, ks = 0.3, n = 10, colour (1, 0.5, 0.25); a light of intensity 2 at distance
  // 2 with the physical falloff 1 / d^2 = 0.25, at 45 degrees (N.L = 0.7071068), viewer at
  // 30 degrees opposite ((R.V)^10 = 0.7070299):
  //   I = 2 * 0.25 * (0.7 colour 0.7071068 + 0.3 * 0.7070299)
  //     = (0.3535419, 0.2297982, 0.1679263).
  const Material m = classicMaterial(MaterialType::Phong);
  const Vec3 L = atAngle(45.0), V = atAngle(-30.0);
  const Vec3 I = classic::lightContribution(m, kUp, V, L, Vec3(2.0), 2.0);
  EXPECT_NEAR(I.x, 0.35354185858842085, 1e-12);
  EXPECT_NEAR(I.y, 0.22979817188077506, 1e-12);
  EXPECT_NEAR(I.z, 0.16792632852695213, 1e-12);
  // The parts: diffuse kd colour N.L, specular ks (R.V)^n.
  EXPECT_NEAR(classic::diffuseTerm(m, kUp, L).y, 0.7 * 0.5 * std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(classic::specularTerm(m, kUp, V, L), 0.3 * 0.7070299011541948, 1e-13);
  // The light's colour tints both parts: a red light gives a red highlight.
  const Vec3 red = classic::lightContribution(m, kUp, V, L, Vec3(2.0, 0.0, 0.0), 2.0);
  EXPECT_NEAR(red.x, I.x, 1e-15);
  EXPECT_EQ(red.y, 0.0);
  // A light under the surface adds nothing.
  EXPECT_TRUE(isZero(classic::lightContribution(m, kUp, V, -L, Vec3(2.0), 2.0)));
}

TEST(ClassicShading, 03_DistanceAttenuationAndAmbient) {
  // OpenGL's 1 / (c + l d + q d^2): [1, 0.1, 0.01] at d = 10 gives 1 / (1 + 1 + 1) = 1/3;
  // [0, 0, 1] is 1 / d^2; [1, 0, 0] no falloff at all.
  EXPECT_NEAR(classic::distanceAttenuation({1.0, 0.1, 0.01}, 10.0), 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(classic::distanceAttenuation({0.0, 0.0, 1.0}, 4.0), 1.0 / 16.0, 1e-15);
  EXPECT_EQ(classic::distanceAttenuation({1.0, 0.0, 0.0}, 1e6), 1.0);
  // The ambient term is ka Ia times the colour, whatever the lights do.
  Material m = classicMaterial(MaterialType::Phong);
  m.ambient = Vec3(0.2, 0.4, 0.8);
  const Vec3 a = classic::ambientTerm(m);
  EXPECT_NEAR(a.x, 0.2, 1e-15);
  EXPECT_NEAR(a.y, 0.2, 1e-15);
  EXPECT_NEAR(a.z, 0.2, 1e-15);
}

/// A Phong or Blinn-Phong floor at y = 0, a point light of intensity 5 at (1, 2, 0) and a
/// one-pixel camera at (0, 4, 1) looking at the origin (as Algorithms.02).
Scene floorScene(const Material& m) {
  Scene scene;
  const int floor = addMaterial(scene, m);
  addObject(scene, "floor",
            std::make_unique<Quad>(Point3(-5, 0, 5), Vec3(10, 0, 0), Vec3(0, 0, -10)), floor);
  PointLight light;
  light.name = "bulb";
  light.position = Point3(1.0, 2.0, 0.0);
  light.intensity = Vec3(5.0);
  scene.pointLights.push_back(light);
  scene.camera.position = Point3(0.0, 4.0, 1.0);
  scene.camera.lookAt = Point3(0.0);
  scene.camera.width = scene.camera.height = 1;
  return scene;
}

/// Test 04's floor: a `type` material with ambient 0.1 and attenuation [1, 0.5, 0.25] seen at
/// the origin of floorScene, and what the textbook's model gives there with the diffuse
/// term's N.L taken as `nDotL`: 0.1 colour + 5 f_att (0.7 colour N.L + 0.3 highlight^10).
struct TextbookFloor {
  Material material;
  Vec3 expected;
};

TextbookFloor textbookFloor(MaterialType type, double nDotL) {
  const Vec3 L = Vec3(1, 2, 0) / std::sqrt(5.0), V = Vec3(0, 4, 1) / std::sqrt(17.0);
  const double fAtt = 1.0 / (1.0 + 0.5 * std::sqrt(5.0) + 0.25 * 5.0);
  TextbookFloor floor{classicMaterial(type), Vec3(0.0)};
  Material& m = floor.material;
  m.ambient = Vec3(0.1);
  m.attenuation = Vec3(1.0, 0.5, 0.25);
  const double highlight = type == MaterialType::Phong ? std::pow(8.0 / std::sqrt(85.0), 10.0)
                                                       : std::pow(glm::normalize(L + V).y, 10.0);
  floor.expected = 0.1 * m.colour + 5.0 * fAtt * (0.7 * m.colour * nDotL + Vec3(0.3 * highlight));
  return floor;
}

TEST(ClassicShading, 04_RayCastingWhittedAndDistributedShadeByTheTextbook) {
  // At the origin: L = (1, 2, 0) / sqrt 5, N.L = 2 / sqrt 5 = 0.8944272, d = sqrt 5;
  // V = (0, 4, 1) / sqrt 17; R = (-1, 2, 0) / sqrt 5, R.V = 8 / sqrt 85 = 0.8677218;
  // H = (L + V) / |L + V|. With attenuation [1, 0.5, 0.25]:
  // f_att = 1 / (1 + 0.5 sqrt 5 + 0.25 * 5) = 0.2969091. Ambient (0.1, 0.1, 0.1).
  // I = 0.1 colour + 5 f_att (0.7 colour 0.8944272 + 0.3 highlight^10).
  EXPECT_NEAR(1.0 / (1.0 + 0.5 * std::sqrt(5.0) + 0.25 * 5.0), 0.2969091, 1e-7);
  for (MaterialType type : {MaterialType::Phong, MaterialType::BlinnPhong}) {
    const TextbookFloor floor = textbookFloor(type, 2.0 / std::sqrt(5.0));
    const Vec3& expected = floor.expected;
    const Scene scene = floorScene(floor.material);
    for (Algorithm algorithm :
         {Algorithm::RayCasting, Algorithm::Whitted, Algorithm::Distributed}) {
      const Vec3 I = Tracer(scene, settingsFor(algorithm, 1)).trace(0, 0, 0);
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(I[c], expected[c], 1e-12) << toString(type) << " " << toString(algorithm);
    }
  }
}

TEST(ClassicShading, 05_WhittedFollowsKrAndKt) {
  // A Phong ball (black local model, ambient 0) with kr = 0.5 in front of a wall emitting
  // (2, 3, 4) behind the camera: Whitted returns kr Le = (1, 1.5, 2) (one reflection,
  // white: the colour belongs to the local model); ray casting ignores kr (0).
  Scene scene;
  Material ball = classicMaterial(MaterialType::Phong);
  ball.diffuse = 0.0;
  ball.specular = 0.0;
  ball.reflectionRate = 0.5;
  const int ballM = addMaterial(scene, ball);
  const int lightM = addMaterial(
      scene, makeMaterial("light", MaterialType::Diffuse, Vec3(0.0), Vec3(2.0, 3.0, 4.0)));
  addObject(scene, "ball", std::make_unique<Sphere>(Point3(0.0), 1.0), ballM);
  addObject(scene, "wall",
            std::make_unique<Quad>(Point3(10, -10, 6), Vec3(-20, 0, 0), Vec3(0, 20, 0)), lightM);
  scene.camera.position = Point3(0.0, 0.0, 5.0);
  scene.camera.lookAt = Point3(0.0);
  scene.camera.verticalFov = 2.0;  // jittered rays stay on the ball, nearly head-on
  scene.camera.width = scene.camera.height = 1;
  const Vec3 whitted = Tracer(scene, settingsFor(Algorithm::Whitted, 1)).trace(0, 0, 0);
  EXPECT_NEAR(whitted.x, 1.0, 1e-12);
  EXPECT_NEAR(whitted.y, 1.5, 1e-12);
  EXPECT_NEAR(whitted.z, 2.0, 1e-12);
  EXPECT_TRUE(isZero(Tracer(scene, settingsFor(Algorithm::RayCasting, 1)).trace(0, 0, 0)));

  // kt = 0.8, ior 1.5, kr = 0: the ray passes through the ball head-on (two interfaces,
  // no bending at normal incidence) to a wall emitting 1 behind it: kt^2 Le = 0.64 for
  // Whitted; path tracing's counterpart picks the transmitted lobe every time with weight
  // kt, so it gives the same 0.64 in every sample.
  Scene glass;
  Material clear = ball;
  clear.reflectionRate = 0.0;
  clear.refractionRate = 0.8;
  clear.ior = 1.5;
  const int clearM = addMaterial(glass, clear);
  const int wallM =
      addMaterial(glass, makeMaterial("light", MaterialType::Diffuse, Vec3(0.0), Vec3(1.0)));
  addObject(glass, "ball", std::make_unique<Sphere>(Point3(0.0), 1.0), clearM);
  addObject(glass, "wall",
            std::make_unique<Quad>(Point3(-10, -10, -6), Vec3(20, 0, 0), Vec3(0, 20, 0)), wallM);
  glass.camera = scene.camera;
  EXPECT_NEAR(Tracer(glass, settingsFor(Algorithm::Whitted, 1)).trace(0, 0, 0).y, 0.64, 1e-12);
  const Tracer path(glass, settingsFor(Algorithm::PathTracing, 1));
  for (int s = 0; s < 8; ++s) EXPECT_NEAR(path.trace(0, 0, s).y, 0.64, 1e-12) << s;
}

TEST(ClassicShading, 06_MonteCarloCounterpartNeverCreatesEnergy) {
  // Path tracing's normalised counterpart: textbook coefficients kd = 0.7, ks = 0.5,
  // kr = 0.3 (sum 1.5) are scaled by 1 / 1.5, so the albedo E[weight] stays <= 1; and the
  // sampled weights agree with eval / pdf.
  for (MaterialType type : {MaterialType::Phong, MaterialType::BlinnPhong}) {
    Material m = classicMaterial(type);
    m.colour = Vec3(1.0);
    m.diffuse = 0.7;
    m.specular = 0.5;
    m.reflectionRate = 0.3;
    SurfaceInteraction si;
    si.n = kUp;
    si.frontFace = true;
    for (double degrees : {0.0, 40.0, 80.0}) {
      const Vec3 wo = atAngle(degrees);
      Sampler rng(3, int(degrees), int(type), 0);
      double sum = 0.0;
      const int n = 200000;
      for (int i = 0; i < n; ++i) {
        const auto s = bsdf::sample(m, si, wo, rng);
        if (!s) continue;
        sum += s->weight.y;
        if (!s->specular) {
          const Vec3 expected = bsdf::eval(m, si, wo, s->wi) / bsdf::pdf(m, si, wo, s->wi);
          ASSERT_NEAR(s->weight.y, expected.y, 1e-9 * expected.y);
        }
      }
      // (0.7 + 0.3) / 1.5 = 2/3 from the diffuse and mirror parts alone; the lobe adds up
      // to 0.5 / 1.5 less what it loses below the horizon.
      const double albedo = sum / n;
      EXPECT_LE(albedo, 1.0 + 0.01) << toString(type) << " at " << degrees;
      EXPECT_GE(albedo, 2.0 / 3.0 - 0.01) << toString(type) << " at " << degrees;
    }
  }
}

TEST(ClassicShading, 07_NoCosineFaultLeavesOutNLOfTheDiffuseTermOnly) {
  // The bug hunt's no_cosine (issue 35) on the floor of test 04: the diffuse term loses its
  // N.L, the highlight (which has none in Phong's model) stays as it is:
  // I = 0.1 colour + 5 f_att (0.7 colour + 0.3 highlight^10).
  for (MaterialType type : {MaterialType::Phong, MaterialType::BlinnPhong}) {
    const TextbookFloor floor = textbookFloor(type, 1.0);
    RenderSettings settings = settingsFor(Algorithm::RayCasting, 1);
    settings.fault = Fault::NoCosine;
    const Vec3 I = Tracer(floorScene(floor.material), settings).trace(0, 0, 0);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(I[c], floor.expected[c], 1e-12) << toString(type);
  }
}

TEST(Fresnel, 01_BrewsterAngleAndPolarisations) {
  // Air to glass (eta = 1 / 1.5): Brewster's angle atan(1.5) = 56.30993 degrees; there R_p
  // vanishes and, since theta_i + theta_t = 90 degrees,
  // R_s = sin^2(theta_i - theta_t) = sin^2(22.61986 deg) = (5 / 13)^2 = 25 / 169.
  const double eta = 1.0 / 1.5;
  const double brewster = fresnel::brewsterAngle(eta);
  EXPECT_NEAR(brewster * 180.0 / kPi, 56.309932474020215, 1e-12);
  EXPECT_NEAR(fresnel::reflectanceP(std::cos(brewster), eta), 0.0, 1e-16);
  EXPECT_NEAR(fresnel::reflectanceS(std::cos(brewster), eta), 25.0 / 169.0, 1e-15);
  EXPECT_NEAR(fresnel::dielectric(std::cos(brewster), eta), 12.5 / 169.0, 1e-15);
  // From inside the glass Brewster's angle is the complement: atan(1 / 1.5) = 33.69 deg.
  EXPECT_NEAR(fresnel::brewsterAngle(1.5) + brewster, kPi / 2.0, 1e-15);
  EXPECT_NEAR(fresnel::reflectanceP(std::cos(fresnel::brewsterAngle(1.5)), 1.5), 0.0, 1e-16);
  // Normal incidence: ((n - 1) / (n + 1))^2 = 0.04 both ways, both polarisations.
  for (double e : {eta, 1.5}) {
    EXPECT_NEAR(fresnel::reflectanceS(1.0, e), 0.04, 1e-15);
    EXPECT_NEAR(fresnel::reflectanceP(1.0, e), 0.04, 1e-15);
    EXPECT_NEAR(fresnel::normalIncidence(e), 0.04, 1e-15);
  }
  // R_s grows monotonically to 1 at grazing; R_p dips to 0 at Brewster first.
  double previous = 0.0;
  for (int d = 0; d <= 89; ++d) {
    const double rs = fresnel::reflectanceS(std::cos(radians(d)), eta);
    EXPECT_GE(rs, previous) << d;
    previous = rs;
    EXPECT_LE(fresnel::reflectanceP(std::cos(radians(d)), eta), rs + 1e-15) << d;
  }
  // The old entry point is the mean: 60 degrees into glass, R = 0.0891867.
  EXPECT_NEAR(bsdf::fresnelDielectric(0.5, eta), 0.08918671280221281, 1e-14);
  EXPECT_NEAR(fresnel::dielectric(0.5, eta), 0.08918671280221281, 1e-14);
}

TEST(Fresnel, 02_TotalInternalReflection) {
  // Glass to air: the critical angle is asin(1 / 1.5) = 41.81 degrees. Past it every
  // reflectance is 1; just before it both are below 1.
  const double critical = std::asin(1.0 / 1.5);
  EXPECT_NEAR(critical * 180.0 / kPi, 41.8103149, 1e-6);
  const double past = std::cos(critical + 1e-6), before = std::cos(critical - 1e-3);
  EXPECT_EQ(fresnel::reflectanceS(past, 1.5), 1.0);
  EXPECT_EQ(fresnel::reflectanceP(past, 1.5), 1.0);
  EXPECT_EQ(fresnel::schlickDielectric(past, 1.5), 1.0);
  EXPECT_LT(fresnel::reflectanceS(before, 1.5), 1.0);
  EXPECT_LT(fresnel::reflectanceP(before, 1.5), 1.0);
  EXPECT_LT(fresnel::schlickDielectric(before, 1.5), 1.0);
}

TEST(Fresnel, 03_SchlickByHand) {
  // F = F0 + (1 - F0) (1 - cos)^5 with F0 = 0.04: at 60 degrees into glass
  // 0.04 + 0.96 / 32 = 0.07 (exact: 0.0891867); at grazing 1; head-on 0.04.
  const double eta = 1.0 / 1.5;
  EXPECT_NEAR(fresnel::schlickDielectric(0.5, eta), 0.07, 1e-15);
  EXPECT_NEAR(fresnel::schlickDielectric(0.0, eta), 1.0, 1e-15);
  EXPECT_NEAR(fresnel::schlickDielectric(1.0, eta), 0.04, 1e-15);
  EXPECT_NEAR(fresnel::schlick(0.5, 0.04), 0.07, 1e-15);
  const Vec3 gold = fresnel::schlick(0.5, Vec3(1.0, 0.78, 0.34));
  EXPECT_NEAR(gold.z, 0.34 + 0.66 / 32.0, 1e-15);
  // Inside glass at 30 degrees: the curve is taken at the transmitted angle,
  // sin theta_t = 1.5 * 0.5 = 0.75, cos theta_t = 0.6614378,
  // F = 0.04 + 0.96 (1 - 0.6614378)^5 = 0.0442703 (exact: 0.0551902).
  EXPECT_NEAR(fresnel::schlickDielectric(std::cos(radians(30.0)), 1.5), 0.04427034925264154, 1e-14);
  // So Schlick is symmetric like the exact Fresnel: the same value from either side of
  // the same pair of angles.
  for (int d = 0; d < 90; d += 7) {
    const double cosI = std::cos(radians(d));
    const double cosT = std::sqrt(1.0 - std::pow(std::sin(radians(d)) / 1.5, 2.0));
    EXPECT_NEAR(fresnel::schlickDielectric(cosI, eta), fresnel::schlickDielectric(cosT, 1.5), 1e-14)
        << d;
    EXPECT_NEAR(fresnel::dielectric(cosI, eta), fresnel::dielectric(cosT, 1.5), 1e-14) << d;
  }
  // Largest error of Schlick against the exact curve for glass, over 0..90 degrees in
  // 0.01-degree steps: 0.0357 (near 80 degrees), the figure usually quoted as "a few %".
  double worst = 0.0;
  for (int i = 0; i <= 9000; ++i) {
    const double c = std::cos(radians(i / 100.0));
    worst =
        std::max(worst, std::abs(fresnel::schlickDielectric(c, eta) - fresnel::dielectric(c, eta)));
  }
  EXPECT_NEAR(worst, 0.03569261927668321, 1e-9);
}

TEST(Fresnel, 04_DielectricMaterialChoosesItsModel) {
  // A Dielectric material at 60 degrees splits R and 1 - R by its Fresnel model:
  // exact 0.0891867, Schlick 0.07.
  Material glass = makeMaterial("glass", MaterialType::Dielectric, Vec3(1.0));
  glass.ior = 1.5;
  SurfaceInteraction si;
  si.n = kUp;
  si.frontFace = true;
  const Vec3 wo = atAngle(60.0);
  SpecularLobes lobes = bsdf::specularLobes(glass, si, wo);
  ASSERT_EQ(lobes.count, 2);
  EXPECT_NEAR(lobes.lobe[0].weight.x, 0.08918671280221281, 1e-14);
  glass.fresnel = FresnelModel::Schlick;
  lobes = bsdf::specularLobes(glass, si, wo);
  ASSERT_EQ(lobes.count, 2);
  EXPECT_NEAR(lobes.lobe[0].weight.x, 0.07, 1e-14);
  EXPECT_NEAR(lobes.lobe[1].weight.x, 0.93, 1e-14);
}

TEST(NestedMedia, 01_WaterAgainstGlassRefractsWithBothIndices) {
  // Water (1.33) inside glass (1.5): its surface has "ior": 1.33, "ior_outside": 1.5. From
  // the glass side at 30 degrees Snell gives sin theta_t = 1.5 / 1.33 * 0.5 = 0.5639098,
  // theta_t = 34.32662 degrees, and Fresnel R = 0.0041646 (eta = 1.5 / 1.33); from the water
  // side at 30 degrees, sin theta_t = 1.33 / 1.5 * 0.5, theta_t = 26.31676 degrees; from the
  // glass side past asin(1.33 / 1.5) = 62.457 degrees all light is reflected.
  Material water = makeMaterial("water", MaterialType::Dielectric, Vec3(1.0));
  water.ior = 1.33;
  water.iorOutside = 1.5;
  SurfaceInteraction si;
  si.n = kUp;
  si.frontFace = true;
  SpecularLobes lobes = bsdf::specularLobes(water, si, atAngle(30.0));
  ASSERT_EQ(lobes.count, 2);
  EXPECT_NEAR(lobes.lobe[0].weight.x, 0.00416463337760042, 1e-14);
  const double degreesOut = std::acos(-lobes.lobe[1].wi.y) * 180.0 / kPi;
  EXPECT_NEAR(degreesOut, 34.32661830540913, 1e-9);
  si.frontFace = false;  // wo in the water, below the surface
  const Vec3 below(-std::sin(radians(30.0)), -std::cos(radians(30.0)), 0.0);
  lobes = bsdf::specularLobes(water, si, below);
  ASSERT_EQ(lobes.count, 2);
  EXPECT_NEAR(std::acos(lobes.lobe[1].wi.y) * 180.0 / kPi, 26.31675512821712, 1e-9);
  si.frontFace = true;
  lobes = bsdf::specularLobes(water, si, atAngle(63.0));
  ASSERT_EQ(lobes.count, 1);
  EXPECT_EQ(lobes.lobe[0].kind, RayKind::Reflection);
  EXPECT_EQ(lobes.lobe[0].weight.x, 1.0);
  EXPECT_EQ(bsdf::specularLobes(water, si, atAngle(62.0)).count, 2);
}

TEST(NestedMedia, 02_WhittedThroughGlassAndWaterHeadOn) {
  // A glass block (1.5) with a block of water (1.33) inside, seen head-on in front of a
  // wall emitting 1. With maxDepth 4 only the straight path counts: four interfaces,
  // air-glass R1 = (0.5 / 2.5)^2 = 0.04 and glass-water R2 = (0.17 / 2.83)^2 = 0.0036085,
  // L = (1 - R1)^2 (1 - R2)^2 = 0.9149608. Were the water's surface taken against air
  // (ior_outside 1) it would be R2' = (0.33 / 2.33)^2 = 0.0200593 and L = 0.8853.
  auto run = [](double waterOutside) {
    Scene scene;
    Material glass = makeMaterial("glass", MaterialType::Dielectric, Vec3(1.0));
    glass.ior = 1.5;
    Material water = makeMaterial("water", MaterialType::Dielectric, Vec3(1.0));
    water.ior = 1.33;
    water.iorOutside = waterOutside;
    const int glassM = addMaterial(scene, glass);
    const int waterM = addMaterial(scene, water);
    const int lightM =
        addMaterial(scene, makeMaterial("light", MaterialType::Diffuse, Vec3(0.0), Vec3(1.0)));
    addObject(scene, "glass", std::make_unique<Box>(Point3(0.0), Vec3(4.0, 4.0, 1.0)), glassM);
    addObject(scene, "water", std::make_unique<Box>(Point3(0.0), Vec3(2.0, 2.0, 0.5)), waterM);
    addObject(scene, "wall",
              std::make_unique<Quad>(Point3(-10, -10, -3), Vec3(20, 0, 0), Vec3(0, 20, 0)), lightM);
    scene.camera.position = Point3(0.0, 0.0, 5.0);
    scene.camera.lookAt = Point3(0.0);
    scene.camera.width = scene.camera.height = 1;
    RenderSettings settings = settingsFor(Algorithm::Whitted, 1);
    settings.maxDepth = 4;
    return Tracer(scene, settings).trace(0, 0, 0).y;
  };
  EXPECT_NEAR(run(1.5), 0.9149608397246108, 1e-12);
  EXPECT_NEAR(run(1.0), 0.96 * 0.96 * std::pow(1.0 - std::pow(0.33 / 2.33, 2.0), 2.0), 1e-12);
}

TEST(NestedMedia, 03_TheGlassOfWaterLessonSceneLoads) {
  // The shipped scene: glass (1.5 in air), water inside it (1.33 against glass), an air
  // bubble in the water (1.0 against water).
  const Scene s =
      SceneIO::load(std::string(RAYLAB_SOURCE_DIR) + "/lessons/scenes/glass-of-water.json");
  const Material& water = s.materials[std::size_t(s.findMaterial("water"))];
  EXPECT_EQ(water.ior, 1.33);
  EXPECT_EQ(water.iorOutside, 1.5);
  const Material& bubble = s.materials[std::size_t(s.findMaterial("air bubble"))];
  EXPECT_EQ(bubble.ior, 1.0);
  EXPECT_EQ(bubble.iorOutside, 1.33);
  // A camera ray through the middle of the picture crosses glass, water and back.
  const Tracer tracer(s, settingsFor(Algorithm::Whitted, 1));
  const Vec3 L = tracer.trace(s.camera.width / 2, s.camera.height / 2, 0);
  EXPECT_TRUE(std::isfinite(L.x) && L.x > 0.0);
}

std::string loadError(const std::string& text) {
  try {
    SceneIO::parse(text, "shading.json");
  } catch (const SceneIO::LoadError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ShadingModelFiles, 01_NewMaterialsRoundTrip) {
  // Every new material type and parameter survives a write and a read, and the writer
  // always writes a material's own parameters (the window's form is made from them).
  const std::string text = R"({"raylab_scene": 2,
    "materials": [
      {"name": "plastic", "type": "phong", "colour": [0.8, 0.2, 0.2], "ambient": [0.1, 0.1, 0.1],
       "diffuse": 0.7, "specular": 0.3, "exponent": 32, "reflection_rate": 0.2,
       "attenuation": [1, 0.1, 0.01]},
      {"name": "blinn", "type": "blinn_phong", "refraction_rate": 0.5, "ior": 1.33},
      {"name": "gold", "type": "rough_conductor", "colour": [1, 0.78, 0.34], "roughness": 0.2,
       "distribution": "beckmann", "visible_normals": false},
      {"name": "frosted", "type": "rough_dielectric", "ior": 1.5, "roughness": 0.1,
       "fresnel": "schlick"},
      {"name": "glass", "type": "dielectric", "fresnel": "schlick", "ior_outside": 1.33}],
    "objects": []})";
  const Scene s = SceneIO::parse(text, "shading.json");
  ASSERT_EQ(s.materials.size(), 5u);
  const Material& plastic = s.materials[0];
  EXPECT_EQ(plastic.type, MaterialType::Phong);
  EXPECT_EQ(plastic.ambient, Vec3(0.1));
  EXPECT_EQ(plastic.diffuse, 0.7);
  EXPECT_EQ(plastic.reflectionRate, 0.2);
  EXPECT_EQ(plastic.attenuation, Vec3(1.0, 0.1, 0.01));
  // A classic material reflects nothing unless told (the mirror's default is 1).
  EXPECT_EQ(s.materials[1].type, MaterialType::BlinnPhong);
  EXPECT_EQ(s.materials[1].reflectionRate, 0.0);
  EXPECT_EQ(s.materials[1].refractionRate, 0.5);
  EXPECT_EQ(s.materials[2].distribution, MicrofacetModel::Beckmann);
  EXPECT_FALSE(s.materials[2].visibleNormals);
  EXPECT_EQ(s.materials[3].fresnel, FresnelModel::Schlick);
  EXPECT_EQ(s.materials[4].fresnel, FresnelModel::Schlick);
  EXPECT_EQ(s.materials[4].iorOutside, 1.33);

  const std::string written = SceneIO::serialize(s);
  EXPECT_EQ(SceneIO::serialize(SceneIO::parse(written, "again.json")), written);
  for (const char* key :
       {"\"ambient\"", "\"diffuse\"", "\"attenuation\"", "\"roughness\"",
        "\"distribution\": \"beckmann\"", "\"visible_normals\"", "\"fresnel\": \"schlick\"",
        "\"blinn_phong\"", "\"rough_dielectric\"", "\"ior_outside\": 1.33"})
    EXPECT_THAT(written, HasSubstr(key));
}

TEST(ShadingModelFiles, 02_ErrorsNameTheFileThePlaceAndTheProblem) {
  const std::string head = R"({"raylab_scene": 2, "objects": [], "materials": [)";
  const struct {
    std::string material;
    const char* expected;
  } cases[] = {
      {R"({"name": "m", "type": "phongg"})",
       "at /materials/0/type: unknown material type \"phongg\""},
      {R"({"name": "m", "type": "phong", "diffuse": 1.5})",
       "at /materials/0/diffuse: diffuse (kd) must be in [0, 1]"},
      {R"({"name": "m", "type": "phong", "ambient": [0, -1, 0]})",
       "at /materials/0/ambient: ambient must not be negative"},
      {R"({"name": "m", "type": "phong", "attenuation": [0, 0, 0]})",
       "at /materials/0/attenuation: attenuation [0, 0, 0] divides by zero"},
      {R"({"name": "m", "type": "phong", "attenuation": [1, -0.1, 0]})",
       "at /materials/0/attenuation: attenuation coefficients [c, l, q] must not be negative"},
      {R"({"name": "m", "type": "phong", "attenuation": 2})",
       "at /materials/0/attenuation: expected [x, y, z]"},
      {R"({"name": "m", "type": "dielectric", "fresnel": "fast"})",
       "at /materials/0/fresnel: unknown Fresnel model \"fast\" (expected exact or schlick)"},
      {R"({"name": "m", "type": "rough_conductor", "distribution": "phong"})",
       "at /materials/0/distribution: unknown microfacet distribution \"phong\""},
      {R"({"name": "m", "type": "rough_conductor", "roughness": 0})",
       "at /materials/0/roughness: roughness (alpha) must be in [0.0001, 4], got 0"},
      {R"({"name": "m", "type": "rough_dielectric", "visible_normals": "yes"})",
       "at /materials/0/visible_normals: expected true or false"},
      {R"({"name": "m", "type": "dielectric", "ior_outside": 0})",
       "at /materials/0/ior_outside: ior_outside (index of the medium outside) must be positive"},
  };
  for (const auto& c : cases) {
    const std::string message = loadError(head + c.material + "]}");
    EXPECT_THAT(message, HasSubstr("shading.json: ")) << message;
    EXPECT_THAT(message, HasSubstr(c.expected)) << message;
  }
}

}  // namespace
}  // namespace raylab
