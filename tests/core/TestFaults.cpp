// Bug-hunt faults (issue 35): RenderSettings::fault plants a typical student bug in the
// engine; each changes the picture or the tree the way that bug does, and none is on unless
// asked for.
#include "LessonFixture.h"

#include "raylab/core/Fresnel.h"
#include "raylab/core/Lesson.h"
#include "raylab/core/Phrases.h"
#include "raylab/core/PixelTrace.h"
#include "raylab/core/RayInspector.h"
#include "raylab/core/RenderSettings.h"
#include "raylab/core/Renderer.h"
#include "raylab/core/Scene.h"
#include "raylab/core/Tracer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

namespace raylab {
namespace {

/// The default scene at 64 x 48 with `algorithm`, `spp` samples and `fault`.
FloatImage render(Algorithm algorithm, int spp, Fault fault) {
  Scene scene = defaultScene();
  scene.camera.width = 64;
  scene.camera.height = 48;
  RenderSettings settings = scene.render;
  settings.algorithm = algorithm;
  settings.samplesPerPixel = spp;
  settings.fault = fault;
  Renderer renderer(scene, settings);
  renderer.setThreads(2);
  return renderer.render();
}

double mean(const FloatImage& image) {
  double sum = 0.0;
  for (const auto& p : image.pixels) sum += double(p.x) + p.y + p.z;
  return sum / (3.0 * double(image.pixels.size()));
}

/// The fraction of pixels whose brightness in `faulty` is below `factor` times `clean`'s.
double darkerFraction(const FloatImage& clean, const FloatImage& faulty, double factor) {
  int darker = 0;
  for (std::size_t i = 0; i < clean.pixels.size(); ++i) {
    const double a = double(clean.pixels[i].x) + clean.pixels[i].y + clean.pixels[i].z;
    const double b = double(faulty.pixels[i].x) + faulty.pixels[i].y + faulty.pixels[i].z;
    darker += b < factor * a ? 1 : 0;
  }
  return double(darker) / double(clean.pixels.size());
}

TEST(Faults, 01_EveryFaultHasAWordAndADescriptionInBothLanguages) {
  EXPECT_EQ(RenderSettings{}.fault, Fault::None);  // never on unless asked for
  for (int i = 0; i < kFaultCount; ++i) {
    const Fault fault = Fault(i);
    ASSERT_EQ(parseFault(toString(fault)), fault);
    const std::string key = std::string("fault.") + toString(fault);
    const std::string en = phrase(key, Language::English);
    const std::string zh = phrase(key, Language::Chinese);
    EXPECT_FALSE(en.empty()) << key;
    EXPECT_NE(en, key) << key << " has no English words";
    EXPECT_NE(zh, en) << key << " has no Chinese words";
  }
  EXPECT_FALSE(parseFault("no_cos"));
}

TEST(Faults, 02_NoFaultRendersTheSameImageAsBefore) {
  // Fault::None is the engine as it is: bit for bit the default settings' image.
  Scene scene = defaultScene();
  scene.camera.width = 32;
  scene.camera.height = 24;
  RenderSettings plain = scene.render;
  plain.samplesPerPixel = 2;
  RenderSettings none = plain;
  none.fault = Fault::None;
  EXPECT_EQ(Renderer(scene, plain).render().pixels, Renderer(scene, none).render().pixels);
  EXPECT_EQ(plain.toString().find("fault"), std::string::npos);
}

TEST(Faults, 03_NoOffsetShowsShadowAcne) {
  const FloatImage clean = render(Algorithm::Whitted, 1, Fault::None);
  const FloatImage acne = render(Algorithm::Whitted, 1, Fault::NoOffset);
  // Speckles: some pixels much darker, as their shadow rays hit their own surface.
  const double speckled = darkerFraction(clean, acne, 0.7);
  std::cout << "pixels darkened by acne: " << speckled << "\n";
  EXPECT_GT(speckled, 0.02) << speckled;
  EXPECT_LT(mean(acne), mean(clean));
}

TEST(Faults, 04_NoCosineMakesGrazingLightAsBrightAsHeadOn) {
  const FloatImage clean = render(Algorithm::RayCasting, 1, Fault::None);
  const FloatImage faulty = render(Algorithm::RayCasting, 1, Fault::NoCosine);
  // Without N.L (at most 1) no pixel gets darker, and the image gets brighter.
  EXPECT_EQ(darkerFraction(clean, faulty, 0.999), 0.0);
  std::cout << "brightness ratio without cos: " << mean(faulty) / mean(clean) << "\n";
  EXPECT_GT(mean(faulty), 1.15 * mean(clean)) << mean(faulty) << " against " << mean(clean);
}

TEST(Faults, 05_EtaInvertedBendsTheRefractedRayAwayFromTheNormal) {
  // A camera ray onto the red sphere (ior 1.5) at 20..50 degrees from its normal: the
  // refracted ray bends towards the normal; with eta inverted, away from it (or not at all:
  // total internal reflection).
  const Scene scene = defaultScene();
  RenderSettings settings = scene.render;
  settings.algorithm = Algorithm::Whitted;
  const int sphere = scene.findObject("red sphere");
  const Tracer clean(scene, settings);
  settings.fault = Fault::EtaInverted;
  const Tracer faulty(scene, settings);
  // The angle to the inward normal of the camera ray and of its refraction child (-1: none).
  const auto angles = [&](const Tracer& tracer, int x, int y) {
    const RayTree tree = tracePixel(tracer, x, y).tree;
    const RaySegment& camera = tree.segments[0];
    std::pair<double, double> a{-1.0, -1.0};
    if (camera.object != sphere) return a;
    const Vec3 inward = -glm::normalize(Vec3(camera.normal));
    a.first = std::acos(std::abs(glm::dot(camera.direction, inward)));
    for (int c = 0; c < camera.childCount; ++c) {
      const RaySegment& child = tree.segments[std::size_t(camera.firstChild + c)];
      if (child.kind == RayKind::Refraction)
        a.second = std::acos(std::abs(glm::dot(child.direction, inward)));
    }
    return a;
  };
  int checked = 0;
  for (int y = 0; y < scene.camera.height && checked < 5; y += 7)
    for (int x = 0; x < scene.camera.width && checked < 5; x += 7) {
      const auto [incident, refracted] = angles(clean, x, y);
      if (incident < 0.35 || incident > 0.87) continue;
      ASSERT_GE(refracted, 0.0);
      EXPECT_LT(refracted, incident) << x << ", " << y;  // Snell: towards the normal
      const auto [same, bent] = angles(faulty, x, y);
      EXPECT_DOUBLE_EQ(same, incident);
      EXPECT_TRUE(bent < 0.0 || bent > incident) << x << ", " << y << ": " << bent;
      ++checked;
    }
  EXPECT_EQ(checked, 5);
}

TEST(Faults, 06_AFlippedNormalDarkensTheLitSurfaces) {
  const FloatImage clean = render(Algorithm::Whitted, 1, Fault::None);
  const FloatImage faulty = render(Algorithm::Whitted, 1, Fault::FlippedNormal);
  const double ratio = mean(faulty) / mean(clean);
  std::cout << "brightness ratio with a flipped normal: " << ratio << "\n";
  EXPECT_LT(ratio, 0.5) << ratio;
  EXPECT_GT(darkerFraction(clean, faulty, 0.5), 0.5);
}

TEST(Faults, 07_PathTracingWithoutThePdfGetsTheEnergyWrong) {
  const double clean = mean(render(Algorithm::PathTracing, 8, Fault::None));
  const double faulty = mean(render(Algorithm::PathTracing, 8, Fault::PdfForgotten));
  const double ratio = faulty / clean;
  std::cout << "energy ratio without the pdf: " << ratio << "\n";
  EXPECT_TRUE(ratio < 0.8 || ratio > 1.25) << ratio;
}

TEST(Faults, 08_RouletteWithoutOneOverQLosesEnergy) {
  const double clean = mean(render(Algorithm::PathTracing, 8, Fault::None));
  const double faulty = mean(render(Algorithm::PathTracing, 8, Fault::RouletteUncompensated));
  const double ratio = faulty / clean;
  std::cout << "energy ratio of roulette without 1/q: " << ratio << "\n";
  EXPECT_LT(ratio, 0.97) << ratio;
  EXPECT_GT(ratio, 0.3) << ratio;  // the direct light is still there
}

TEST(Faults, 09_TheFaultIsPartOfTheSettingsWords) {
  RenderSettings settings;
  settings.fault = Fault::NoCosine;
  EXPECT_NE(settings.toString().find("fault=no_cosine"), std::string::npos);
}

/// A one-step lesson on the lesson suites' fixture scene; `fault` is the step's "fault"
/// member as JSON (empty: none).
std::string faultLesson(const std::string& fault) {
  return std::string(R"({"raylab_lesson": 1, "id": "90-bug-hunt",
    "title": {"en": "Bug hunt", "zh": "找错误"},
    "summary": {"en": "Find the bug.", "zh": "找出错误。"},
    "scene": "scene.json", "defaults": {"algorithm": "whitted", "pixel": [160, 100]},
    "steps": [{"title": {"en": "Which bug?", "zh": "是哪个错误？"},
               "text": {"en": "Look at the tree.", "zh": "观察光线树。"})") +
         (fault.empty() ? "" : R"(, "fault": )" + fault) + "}]}";
}

std::string fixtureOrigin() {
  return (testing::writeLessonScene({"faults-", "bug hunt", "whitted", false}) / "hunt.json")
      .string();
}

TEST(Faults, 10_ALessonStepPlantsItsFaultInItsSceneOnly) {
  const Lesson plain = LessonIO::parse(faultLesson(""), fixtureOrigin());
  EXPECT_EQ(plain.steps.at(0).scene->render.fault, Fault::None);
  const Lesson hunt = LessonIO::parse(faultLesson(R"("eta_inverted")"), fixtureOrigin());
  EXPECT_EQ(hunt.steps.at(0).scene->render.fault, Fault::EtaInverted);
  EXPECT_EQ(hunt.scene->render.fault, Fault::None);  // the lesson's own scene is untouched
}

TEST(Faults, 11_AnUnknownFaultNamesThePlaceAndTheFaults) {
  std::string message = "no error";
  try {
    LessonIO::parse(faultLesson(R"("no_cos")"), fixtureOrigin());
  } catch (const LessonIO::LoadError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("hunt.json"), std::string::npos) << message;
  EXPECT_NE(message.find("/steps/0/fault"), std::string::npos) << message;
  EXPECT_NE(message.find("unknown fault \"no_cos\""), std::string::npos) << message;
  EXPECT_NE(message.find("roulette_uncompensated"), std::string::npos) << message;
}

TEST(Faults, 12_SchlickWithTheWrongSignReflectsEverythingButOnlyWhereSchlickIsUsed) {
  // Schlick 1994: F0 + (1 - F0)(1 - cos)^5 with cos = -d.n >= 0: 0.04 for glass seen head-on.
  // With d.n (< 0) the curve starts at 1 + |cos|, so R = 1 at every angle.
  EXPECT_NEAR(fresnel::schlickDielectric(1.0, 1.0 / 1.5), 0.04, 1e-12);
  EXPECT_EQ(fresnel::schlickWrongSign(1.0, 1.0 / 1.5), 1.0);
  EXPECT_EQ(fresnel::schlickWrongSign(0.2, 1.0 / 1.5), 1.0);
  // The red sphere of the default scene reflects kr R and refracts kt (1 - R) by `model`.
  // The camera ray's children at pixels on it: the weight of the refracted ray, the R the
  // inspector explains for the reflected one (-1: no such child).
  const auto children = [](FresnelModel model, Fault fault, int x, int y) {
    Scene scene = defaultScene();
    scene
        .materials[std::size_t(scene.objects[std::size_t(scene.findObject("red sphere"))].material)]
        .rateFresnel = model;
    scene.render.algorithm = Algorithm::Whitted;
    scene.render.fault = fault;
    const RayTree tree = tracePixel(Tracer(scene, scene.render), x, y).tree;
    std::pair<double, double> found{-1.0, -1.0};
    if (tree.segments[0].object != scene.findObject("red sphere")) return found;
    for (int c = 0; c < tree.segments[0].childCount; ++c) {
      const int id = tree.segments[0].firstChild + c;
      const RaySegment& child = tree.segments[std::size_t(id)];
      if (child.kind == RayKind::Refraction) found.first = child.weight.x;
      if (child.kind == RayKind::Reflection)
        found.second = RayInspector::inspect(scene, tree, id, false).rateWeight->share;
    }
    return found;
  };
  int checked = 0;
  for (int y = 0; y < 240 && checked < 4; y += 9)
    for (int x = 0; x < 320 && checked < 4; x += 9) {
      const auto [refracted, R] = children(FresnelModel::Schlick, Fault::None, x, y);
      if (refracted < 0.0) continue;
      EXPECT_GT(refracted, 0.1) << x << ", " << y;  // kt (1 - R), R small away from grazing
      EXPECT_LT(R, 0.5) << x << ", " << y;
      // The fault: no refracted ray, and the inspector's R is 1.
      const auto [none, one] = children(FresnelModel::Schlick, Fault::SchlickWrongSign, x, y);
      EXPECT_EQ(none, -1.0) << x << ", " << y;
      EXPECT_EQ(one, 1.0) << x << ", " << y;
      // The exact Fresnel equations are not Schlick's: the fault leaves them alone.
      EXPECT_EQ(children(FresnelModel::Exact, Fault::SchlickWrongSign, x, y),
                children(FresnelModel::Exact, Fault::None, x, y));
      ++checked;
    }
  EXPECT_EQ(checked, 4);
}

}  // namespace
}  // namespace raylab
