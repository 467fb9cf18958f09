#pragma once

#include "raylab/core/Exception.h"
#include "raylab/core/Language.h"
#include "raylab/core/PixelTrace.h"
#include "raylab/core/Ray.h"
#include "raylab/core/RayTree.h"
#include "raylab/core/RenderSettings.h"
#include "raylab/core/Scene.h"

#include <climits>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace raylab {

/// What a lesson step shows.
enum class LessonView {
  Scene,      ///< "scene": the 3D scene with the ray tree of the step's pixel.
  Image,      ///< "image": the rendered image of the step's algorithm.
  Compare,    ///< "compare": the four algorithms side by side.
  Plot,       ///< "plot": the convergence plot (error against samples or time).
  Inspector,  ///< "inspector": one ray of the tree (select_ray) in the ray inspector.
  Samples,    ///< "samples": a sampler's directions as a point cloud.
};
/// "scene", "image", "compare", "plot", "inspector", "samples".
const char* toString(LessonView view);
std::optional<LessonView> parseLessonView(const std::string& name);

/// How the ray tree is coloured (the ray-tree view's colourings, named as in `raylab trace`).
enum class LessonColouring {
  Energy,  ///< "energy": the original course program's grey-green-blue energy scale.
  Kind,    ///< "kind": camera, reflection, refraction, diffuse, glossy, shadow.
  Depth,   ///< "depth": bounces from the camera ray.
};
const char* toString(LessonColouring colouring);

/// Where the 3D view looks from (as `raylab trace --view`).
enum class LessonCameraView {
  Default,  ///< "default": from outside the scene.
  Camera,   ///< "camera": from just behind the scene's camera.
  CloseUp,  ///< "close_up": close to the mesh of the step's "bvh" block, from the camera's side;
            ///< without one, close to the hit where the selected ray (default: the camera
            ///< ray) bends, square to the plane of its rays (vis::closeUpOnRay).
};
const char* toString(LessonCameraView view);

/// What the comparison and the convergence plot hold equal (as `raylab compare --spp` /
/// `--time` and `raylab plot --x`).
enum class LessonMeasure {
  Samples,  ///< "samples": equal samples per pixel; the plot's x axis is samples.
  Time,     ///< "time": equal rendering time; the plot's x axis is seconds.
};
const char* toString(LessonMeasure measure);

/// How much of the ray tree a step reveals: all of it, up to an animation frame, or up
/// to a depth (every ray of depth <= value).
struct LessonReveal {
  enum class By { Everything, Frame, Depth };
  By by = By::Everything;
  int value = 0;  ///< Frame number or depth, >= 0.
};

/// Which rays of the tree are drawn (as `raylab trace`'s filter options).
struct LessonFilters {
  std::vector<RayKind> kinds;  ///< Only these kinds; empty = every kind.
  int maxDepth = INT_MAX;      ///< Deepest depth drawn (camera ray: 0).
  bool reachingLight = false;  ///< Only rays on paths that found light.
  double minEnergy = 0.0;      ///< Hide rays carrying less energy than this.
};

/// A sampler whose directions the "samples" view draws as a point cloud, in the local
/// frame where the surface normal (or, for the Phong lobe, the mirror direction) is +z.
struct LessonSamples {
  enum class Sampler {
    Cosine,   ///< "cosine": cosine-weighted hemisphere (sampleCosineHemisphere).
    Uniform,  ///< "uniform": uniform hemisphere (sampleUniformSphere folded onto +z).
    Sphere,   ///< "sphere": uniform sphere (sampleUniformSphere).
    Phong,    ///< "phong": normalised Phong lobe of `exponent` (samplePhongLobe).
  };
  Sampler sampler = Sampler::Cosine;
  int count = 256;        ///< Directions drawn, >= 1.
  double exponent = 0.0;  ///< Phong exponent (> 0, required for "phong" only).

  /// The `count` directions the view draws (unit vectors, local frame), the same for the
  /// same seed on every machine.
  std::vector<Vec3> directions(std::uint64_t seed = 0) const;
};
const char* toString(LessonSamples::Sampler sampler);

/**
 * \brief A number a question's answer is computed from, so answers are not typed by hand:
 * computeCheck recomputes it with Tracer / Stepper on the step's scene (scene changes
 * applied), and `raylab lesson FILE --check` (run on every lesson by the test suite) checks
 * the stated answer lies within its tolerance.
 */
struct LessonCheck {
  enum class Quantity {
    TreeRays,           ///< "tree_rays": rays in the recorded tree of one sample (optionally
                        ///< only of `kind`, only those that ended for `end`).
    TreeDepth,          ///< "tree_depth": the deepest depth in that tree (camera ray: 0).
    EstimateLuminance,  ///< "estimate_luminance": luminance of that sample's estimate.
    PixelLuminance,     ///< "pixel_luminance": mean luminance of samples 0..spp-1 of the pixel.
    RayLength,          ///< "ray_length": distance from ray `ray`'s origin to its hit point.
    CameraRays,         ///< "camera_rays": camera rays of a whole image at the scene's spp.
    BvhNodes,           ///< "bvh_nodes": nodes (boxes) of a mesh's BVH, with the step's split.
    BvhBoxesEntered,    ///< "bvh_boxes_entered": boxes of that BVH the camera ray of the
                        ///< pixel's sample enters (Bvh::traceVisits on the mesh alone).
    BvhTriangleTests,   ///< "bvh_triangle_tests": ray/triangle tests that search makes.
    RayTarget,          ///< "ray_target" (choice questions): what ray `ray` of the tree
                        ///< reaches, by name (computeTarget); compared with the choices'
                        ///< "value".
  };
  Quantity quantity = Quantity::TreeRays;
  Algorithm algorithm = Algorithm::PathTracing;  ///< Default: the step's algorithm.
  int pixelX = 0, pixelY = 0;                    ///< Default: the step's pixel.
  int sample = 0;                                ///< Default: the step's sample.
  std::optional<RayKind> kind;                   ///< tree_rays: only this kind.
  std::optional<EndReason> end;                  ///< tree_rays: only rays that ended so.
  int ray = 0;                                   ///< ray_length: the segment id.
  int spp = 0;                                   ///< pixel_luminance: samples (0: scene's).
  int object = -1;  ///< bvh_*: the mesh object (default: the step's bvh object, else the
                    ///< scene's first mesh); an index into the step scene's objects.
  /// The step's chosen ray, traced in place of the pixel's camera ray, when the check
  /// names no pixel of its own and the step has one (LessonStep::ray).
  std::optional<Ray> root;
};
/// "tree_rays", "tree_depth", ...
const char* toString(LessonCheck::Quantity quantity);

/**
 * \brief What a step shows of a mesh's bounding volume hierarchy (lesson 8), drawn in the
 * scene view over the ray tree: the boxes of levels firstLevel..lastLevel in their level's
 * colours, or, with `visits`, only the boxes of those levels that the camera ray of the
 * step's pixel meets (entered thick; missed and culled thin and grey). The hierarchy is
 * the one the step's render settings search (their bvh_split, see RenderSettings).
 */
struct LessonBvh {
  int object = 0;       ///< The mesh object, an index into the step scene's objects.
  int firstLevel = 0;   ///< First level drawn (the root is level 0).
  int lastLevel = 0;    ///< Last level drawn, inclusive (at most the tree's depth).
  bool visits = false;  ///< Only the boxes the step pixel's camera ray meets.
};

/**
 * \brief The order the `count` choices of a multiple-choice question are shown in, the same
 * in the window and in the handout: a permutation fixed by the lesson's id and the step's
 * index (0-based), so that the right answer sits at no favoured place. Element k is the
 * index in the file of the choice shown k-th.
 */
std::vector<int> choiceOrder(const std::string& lessonId, std::size_t stepIndex, std::size_t count);

/// A question for the student: multiple choice, or a number with a tolerance.
struct LessonQuestion {
  enum class Type { Choice, Number };
  Type type = Type::Choice;
  LocalText prompt;
  std::vector<LocalText> choices;    ///< Choice: at least two, in the file's order.
  int answerIndex = 0;               ///< Choice: index into choices (the file's order).
  double answer = 0.0;               ///< Number: the right answer.
  double tolerance = 0.0;            ///< Number: accepted |given - answer|, >= 0.
  std::optional<LessonCheck> check;  ///< How the answer is computed (number; choice: ray_target).
  LocalText explanation;             ///< Why, shown after answering.
  /// "hint": said with the "try again" of a first wrong answer (QuestionAttempts); empty
  /// when the question has none. It must not give the answer away.
  LocalText hint;
  /// "predict": asked before the step's view shows what it is about (the tree, the image,
  /// the effect of a tried value); the window shows it once the answer is final.
  bool predict = false;
  /// Choice: the order the choices are shown in (choiceOrder; "shuffle": false keeps the
  /// file's order, for choices that are a scale). Element k: the file index shown k-th.
  std::vector<int> shownOrder;
  /// Choice with a ray_target check: each choice's "value", the name it stands for.
  std::vector<std::string> choiceValues;

  /// Choice: the place (0-based) the right answer is shown at.
  int shownAnswer() const;
};

/**
 * \brief A value the student changes in a "change a value and predict" step: a number at a
 * place of the scene file (as `--set PLACE=VALUE` and SceneEdit's setValue name it), set to
 * `value` by the task, anywhere in [min, max] by the student in the window.
 */
struct LessonTryValue {
  std::string place;   ///< JSON pointer into the scene file ("/materials/2/ior"), names resolved.
  LocalText label;     ///< What the value is, for the spin box and the handout.
  double value = 0.0;  ///< The value the task asks to set.
  double original = 0.0;        ///< The value in the step's scene.
  double min = 0.0, max = 1.0;  ///< The range the window's spin box allows.
  double step = 0.1;            ///< The spin box's step.
  int decimals = 2;             ///< Decimals the spin box shows.
  std::string sceneFile;        ///< The scene's file (messages; meshes are found beside it).
  /// The step's scene with `value` set: what the step's question is about and its check is
  /// computed on.
  std::shared_ptr<const Scene> triedScene;

  /// The step scene `scene` with the value at `place` set to `v` (SceneEdit::setValue);
  /// throws SceneIO::LoadError when the scene refuses it.
  Scene with(const Scene& scene, double v) const;
};

/// One step of a lesson: what to show, what to read, what to ask.
struct LessonStep {
  /// The most samples a "bundle" draws together.
  static constexpr int kMaxBundle = 256;

  LocalText title;
  LocalText text;
  LessonView view = LessonView::Scene;
  Algorithm algorithm = Algorithm::PathTracing;  ///< Resolved: step, lesson default or scene.
  std::optional<int> pixelX, pixelY;             ///< The pixel traced (both or neither).
  int sample = 0;                                ///< Which sample of the pixel.
  LessonReveal reveal;
  LessonColouring colouring = LessonColouring::Energy;
  LessonFilters filters;
  LessonCameraView cameraView = LessonCameraView::Default;
  std::optional<int> selectRay;          ///< Segment id to select (inspector: default 0).
  std::optional<LessonSamples> samples;  ///< The "samples" view's sampler.
  /// "bundle": samples sample .. sample + bundle - 1 of the pixel are traced and drawn
  /// together (traceBundle); 1 draws the one sample. At most LessonStep::kMaxBundle.
  int bundle = 1;
  /// "all_hits": every surface the pixel's camera ray (the selected ray in the inspector
  /// view) crosses is marked along it, entering and leaving (sceneCrossings).
  bool allHits = false;
  /// "ray": {"origin": [x, y, z], "direction": [x, y, z]}, a ray chosen by hand traced in
  /// place of the pixel's camera ray (traceRay; the pixel, (0, 0) when the step names
  /// none, only chooses the random numbers of the rays it spawns): a ray exactly tangent
  /// to a sphere, or one on the knife edge of a rim. World space; the direction is
  /// normalised.
  std::optional<Ray> ray;
  /// "exactness": the inspector view shows the exact oracle's check of the selected ray's
  /// hit (exact t, double t, their difference in ulps, the bound, the verdict) beside the
  /// ray's values, as the window's "Exactness figures" button does.
  bool exactness = false;
  std::optional<LessonBvh> bvh;                    ///< Scene view: a mesh's BVH boxes.
  LessonMeasure measure = LessonMeasure::Samples;  ///< Compare and plot views only.
  /// The step's scene changes as written (compact JSON, one per change), for captions.
  std::vector<std::string> sceneChanges;
  std::optional<LessonQuestion> question;
  /// "try_value": the value the student changes in a "change a value and predict" step.
  std::optional<LessonTryValue> tryValue;
  LocalText teacherNotes;          ///< Optional; empty when absent.
  double minutes = 0.0;            ///< "minutes": class time planned for the step (0: none).
  bool recap = false;              ///< "recap": the lesson's closing summary.
  std::vector<std::string> needs;  ///< "requires": features the step needs that RayLab lacks.
  /// The step's scene: the lesson's scene with this step's changes applied (shared with
  /// the lesson when the step changes nothing). Never null in a loaded lesson.
  std::shared_ptr<const Scene> scene;

  /// The settings the step renders and traces with: the step scene's render block with
  /// the step's algorithm.
  RenderSettings settings() const;
  /// The camera ray of the step's pixel and sample (world space, the first ray of its
  /// tree, unbounded), or the step's chosen ray; nothing when the step has neither.
  std::optional<Ray> cameraRay() const;
  /// True when the step traces a tree: it names a pixel or a chosen ray.
  bool traces() const { return bool(pixelX) || bool(ray); }
  /// The step's tree: its pixel's sample, or its chosen ray (traceRay); within `limits`.
  /// Call only when traces().
  PixelTrace trace(const TraceLimits& limits = {}) const;
};

/// A lesson: a scene and the steps a class goes through, in English and Chinese.
struct Lesson {
  std::string file;       ///< The lesson file as given to LessonIO::load (or the origin).
  std::string id;         ///< Short name, e.g. "04-whitted".
  LocalText title;        ///< Shown in lists and at the top of the handout.
  LocalText summary;      ///< One paragraph: what the lesson teaches.
  std::string scenePath;  ///< The scene file: "scene" joined to the lesson file's folder.
  std::shared_ptr<const Scene> scene;  ///< The scene as loaded, before any step's changes.
  std::vector<LessonStep> steps;
  std::vector<LocalText> objectives;      ///< "objectives": what a student can do after it.
  std::vector<LocalText> misconceptions;  ///< "misconceptions": what to watch for in class.

  /// Class time planned: the sum of the steps' minutes.
  double minutes() const;
  /// The scene of step `index` (0-based) with its changes applied.
  const Scene& sceneOfStep(std::size_t index) const { return *steps.at(index).scene; }
  /// Number of steps with a question.
  int questionCount() const;
  /// Every distinct feature named by a step's "requires", in order of first use.
  std::vector<std::string> requiredFeatures() const;
};

/// The quantity `check` names, computed by the program on `step`'s scene: what the
/// question's typed answer must equal within its tolerance (`raylab lesson FILE --check`
/// and the test suite compare them). Throws Exception when it cannot be computed (the check's
/// object is not a mesh, its ray is not in the tree or hits nothing, the tree reached its
/// budget).
double computeCheck(const LessonStep& step, const LessonCheck& check);
/// What ray `check.ray` of the check's tree reaches, by name: a shadow ray that reached its
/// light, that light's name; a ray ending on a surface (a shadow ray blocked), that
/// object's name; a ray that escaped, "nothing". Throws Exception as computeCheck.
std::string computeTarget(const LessonStep& step, const LessonCheck& check);
/// The problem with the stated answer of `step`'s question against what the program
/// computes (its check), e.g. "tree_rays: the answer is 4 but the program computes 3";
/// nothing when it matches or the question has no check. Throws Exception as computeCheck.
std::optional<std::string> answerProblem(const LessonStep& step);

/**
 * \brief Reads lesson files: versioned JSON naming a scene in lessons/scenes/ and a list
 * of steps, each in English and Chinese.
 *
 * Format (version 1):
 *
 *     {
 *       "raylab_lesson": 1,
 *       "id": "04-whitted",
 *       "title":   {"en": "Whitted ray tracing", "zh": "Whitted 光线追踪"},
 *       "summary": {"en": "...", "zh": "..."},
 *       "scene": "scenes/whitted.json",
 *       "objectives": [{"en": "Compute refraction with Snell's law.", "zh": "..."}],
 *       "misconceptions": [{"en": "\"Glass casts no shadow.\" ...", "zh": "..."}],
 *       "defaults": {"view": "scene", "algorithm": "whitted", "pixel": [160, 120]},
 *       "steps": [
 *         {"title": {"en": "Snell's law", "zh": "斯涅尔定律"},
 *          "text":  {"en": "The ray meets the glass and splits ...", "zh": "..."},
 *          "view": "scene", "algorithm": "whitted", "pixel": [120, 96], "sample": 0,
 *          "reveal": {"depth": 2}, "colour": "kind",
 *          "filters": {"kinds": ["camera", "refraction"], "max_depth": 3,
 *                      "reaching_light": false, "min_energy": 0},
 *          "camera_view": "default", "select_ray": 1,
 *          "bvh": {"object": "mesh ball", "levels": [0, 2], "visits": false},
 *          "scene_changes": [{"material": "glass", "set": {"ior": 1.0}}],
 *          "question": {"type": "number",
 *                       "prompt": {"en": "How many rays ...?", "zh": "..."},
 *                       "answer": 7, "tolerance": 0,
 *                       "check": {"quantity": "tree_rays", "algorithm": "whitted",
 *                                 "pixel": [120, 96]},
 *                       "explanation": {"en": "...", "zh": "..."}},
 *          "teacher_notes": {"en": "...", "zh": "..."}, "minutes": 3,
 *          "requires": "schlick-fresnel"},
 *         {"title": ..., "text": ..., "view": "scene", "pixel": [99, 120],
 *          "try_value": {"place": "/render/max_depth", "label": {"en": "maximum depth",
 *                        "zh": "最大深度"}, "value": 2, "min": 0, "max": 10, "step": 1},
 *          "question": {"type": "number", "predict": true, "prompt": ..., "answer": 9,
 *                       "check": {"quantity": "tree_rays"}, "explanation": ...}},
 *         {"title": ..., "text": ..., "recap": true, "minutes": 3, ...}
 *       ]
 *     }
 *
 * - "scene" is relative to the lesson file's folder; it is loaded with SceneIO (its
 *   errors are passed on). "defaults" may hold view, algorithm, pixel, sample, reveal,
 *   colour, filters and camera_view; a step inherits each one it does not set. The
 *   algorithm falls back to the scene's render block, the view to "scene".
 * - Step keys: title and text (both {en, zh}, both languages required; "zh" must contain
 *   Chinese); view: scene | image | compare | plot | inspector | samples; algorithm:
 *   raycast | whitted | distributed | path; pixel [x, y] inside the step scene's image
 *   (required by inspector, and by select_ray and reveal, unless the step has a "ray");
 *   ray {"origin": [x, y, z], "direction": [x, y, z]} (world space, finite, at most 1e12,
 *   direction not zero): a ray chosen by hand traced in place of the pixel's camera ray,
 *   e.g. one exactly tangent to a sphere; exactness (inspector view only): true shows the
 *   exact oracle's check of the selected ray beside its values; sample in [0, spp); reveal
 *   {"frame": n} or {"depth": d}; colour: energy | kind | depth; filters (kinds from
 *   camera, reflection, refraction, diffuse, glossy, shadow; max_depth; reaching_light;
 *   min_energy); camera_view: default | camera | close_up (close to the step's bvh mesh;
 *   without "bvh", close to the hit where the selected ray bends, square to the plane of
 *   the rays there, normals drawn; needs a pixel or a ray); select_ray: a segment id of the pixel's
 *   tree (checked by tracing it); samples (view "samples" only): {"sampler": cosine |
 *   uniform | sphere | phong, "count": n, "exponent": e (phong)}; measure (views compare
 *   and plot only): samples | time, what the comparison holds equal and the plot's x axis
 *   (default samples);
 *   bundle (scene and inspector views, needs a pixel): draw samples sample .. sample +
 *   bundle - 1 of the pixel together, 1..256 (a thin lens's camera rays make a bundle);
 *   all_hits (scene and inspector views, needs a pixel): true marks every surface the
 *   camera ray (the inspector's selected ray) crosses, entering and leaving;
 *   bvh (view "scene" only, lesson 8; LessonBvh): {"object": a mesh
 *   object's name (default: the scene's first mesh), "level": d or "levels": [first, last]
 *   (depths from the root, within the tree's depth; default 0, with visits every level),
 *   "visits": true to draw only the boxes the camera ray of the step's pixel meets (needs
 *   a pixel)}; which hierarchy
 *   is drawn, and whether the meshes are searched at all, are render settings, changed
 *   with scene_changes: {"render": {"bvh_split": "median"}}, {"render": {"acceleration":
 *   "none"}}; teacher_notes {en, zh};
 *   requires: a feature name or a list of them (the step needs something RayLab does not
 *   have yet; the loader accepts it and Lesson::requiredFeatures lists it).
 * - scene (a step key): another scene file, relative to the lesson file, that this step
 *   shows instead of the lesson's (lesson 6's glossy plates under lights of four sizes); its
 *   scene_changes edit that scene, and the next step is back on the lesson's scene.
 * - scene_changes: edits for this step only, applied in order to a copy of the scene
 *   file's JSON and validated by SceneIO's own rules, in the scene format's key names:
 *       {"material": NAME, "set": {...}}           merge into the material (not "name")
 *       {"object": NAME, "set": {...}}             merge into the object (e.g. "material",
 *                                                  "velocity", "shape": {"radius": 2})
 *       {"object": NAME, "translate": [x, y, z]}   append a transform step (also "scale"
 *       {"object": NAME, "rotate": {"axis", "degrees"}}   [x, y, z], "rotate")
 *       {"object": NAME, "remove": true}           take the object out
 *       {"point_light": NAME, "set" | "translate" | "remove": ...}
 *       {"camera": {...}}, {"render": {...}}       merge into the camera / render block
 *       {"add_material": {...}}, {"add_object": {...}}, {"add_point_light": {...}}
 *   "set" is a JSON merge patch (RFC 7386): nested objects merge, null removes a key.
 * - question: "type" choice (choices [{en, zh}, ...], "answer" = index) or number
 *   ("answer", "tolerance" >= 0, optional "check"); "prompt" and "explanation" {en, zh}.
 *   "predict": true asks it before the step shows its tree, image or tried value (the
 *   step needs a pixel or a ray, an image view or a try_value); the window shows them once
 *   the answer is final (right, the second try, or "Show answer"). A choice question's
 *   choices are shown in choiceOrder's order ("shuffle": false: the file's order); it may
 *   have a check of quantity "ray_target" ({"ray": n}, "algorithm", "pixel", "sample"), and
 *   then every choice names the object, the light or "nothing" it stands for in "value"
 *   ({"en", "zh", "value"}); the keyed choice's value must be what ray n reaches.
 *   check: {"quantity": tree_rays | tree_depth | estimate_luminance | pixel_luminance |
 *   ray_length | camera_rays | bvh_nodes | bvh_boxes_entered | bvh_triangle_tests,
 *   "algorithm", "pixel", "sample" (default: the step's), "kind", "end" (tree_rays:
 *   escaped, hit_light, max_depth, russian_roulette, absorbed, occluded, reached_light,
 *   spawned), "ray" (ray_length), "spp" (pixel_luminance), "object" (bvh_*: a mesh
 *   object's name; default the step's bvh object, else the first mesh)}.
 * - try_value (a "change a value and predict" step; no scene_changes on the same step, so
 *   that the handout's command line shows the same): {"place": a JSON pointer into the
 *   scene file, whose "materials", "objects" and "point_lights" entries may be named
 *   ("/materials/glass/ior") and must hold a number; "label" {en, zh}; "value": the value
 *   the task asks for, in ["min", "max"]; "step" > 0 (default (max - min) / 100)}. The
 *   scene with the value set is checked by SceneIO's rules; the step's question and its
 *   check are about it.
 * - The teacher's kit: lesson keys "objectives" and "misconceptions" (non-empty lists of
 *   {en, zh}); step keys "minutes" (in (0, 60]), "teacher_notes" {en, zh} and "recap": true
 *   (the closing summary). `raylab lesson --out DIR --student` leaves out every answer,
 *   explanation, note, the plan and the misconceptions.
 * - Unknown keys are errors everywhere (a misspelt key would otherwise be ignored).
 *
 * Every error throws LoadError naming the file, the step (1-based number and English
 * title) and the JSON path, e.g.
 * `lessons/04-whitted.json: step 3 ("Snell's law"): at /steps/2/pixel: pixel (400, 10) is
 * outside the 320x240 image`.
 */
class LessonIO {
 public:
  /// A lesson file that cannot be used: syntax, content, its scene or a scene change.
  class LoadError : public Exception {
   public:
    using Exception::Exception;
  };

  /// The lesson format version this build reads.
  static constexpr int kVersion = 1;

  /// Reads and validates the lesson file at `path` and its scene.
  static Lesson load(const std::string& path);
  /// The title of the lesson file at `path`, for lists of lessons (the window's Lessons
  /// menu): only the JSON, the format version and the title are read and checked, not the
  /// steps nor the scene (which load() builds, meshes included). Throws LoadError as load().
  static LocalText readTitle(const std::string& path);
  /// Parses lesson text; `origin` names it in messages, and the scene path is relative to
  /// its folder (a bare name: the current directory).
  static Lesson parse(const std::string& text, const std::string& origin);
  /// The lesson files in `dir`: names "NN-topic.json" (two digits, a dash), sorted.
  /// Throws LoadError when `dir` is not a readable folder.
  static std::vector<std::string> list(const std::string& dir);
};

}  // namespace raylab
