#include "PropertiesPanel.h"

#include "words/SceneWords.h"

#include "EditPanel.h"
#include "SceneDocument.h"
#include "words/UiWords.h"

#include "raylab/core/AlgorithmInfo.h"
#include "raylab/core/Exception.h"
#include "raylab/core/Phrases.h"
#include "raylab/core/SceneEdit.h"

#include <nlohmann/json.hpp>

#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QTimer>
#include <QVBoxLayout>

#include <cmath>
#include <functional>
#include <set>

namespace raylab::app {

namespace {

using json = nlohmann::ordered_json;

/// Keys whose numbers are whole (spin boxes without decimals).
const std::set<std::string> kIntegerKeys = {
    "m",         "n",    "width",          "height",         "spp",
    "max_depth", "seed", "shadow_samples", "glossy_samples", "russian_roulette_depth",
    "priority"};
/// Keys shown but not edited here: names are references (objects name their material),
/// renaming an object is the Edit panel's; a mesh's file and a matrix are set in files.
const std::set<std::string> kReadOnlyKeys = {"name", "file", "matrix", "type"};
/// Choices of the keys that take one word.
const std::map<std::string, std::vector<const char*>> kChoices = {
    {"algorithm",
     [] {
       std::vector<const char*> words;
       for (Algorithm a : kAllAlgorithms) words.push_back(algorithmInfo(a).word);
       return words;
     }()},
    {"fresnel", {"none", "exact", "schlick"}},
    {"distribution", {"ggx", "beckmann"}},
    {"acceleration", {"bvh", "none"}},
    {"bvh_split", {"sah", "median"}},
    {"near_clip_shape", {"plane", "sphere"}},
    {"normals", {"file", "flat", "smooth"}},
};
const std::vector<const char*> kMaterialTypes = {
    "diffuse",     "mirror",          "dielectric",       "glossy", "phong",
    "blinn_phong", "rough_conductor", "rough_dielectric", "plastic"};

/// `material` (its file form) switched to scattering model `type`: the keys every material
/// has, and those of `type`'s parameters that it had (the others go; the loader gives the
/// missing ones their defaults), so that the form shows exactly that model's fields. The
/// same sets as the scene writer's (core SceneWriter.cpp, materialToJson).
json switchedMaterial(const json& material, const std::string& type) {
  static const std::set<std::string> kEvery = {"name",        "display_name", "colour",
                                               "texture",     "emission",     "opacity",
                                               "ior_outside", "priority"};
  const std::string old = material.value("type", "diffuse");
  const auto in = [](const std::string& t, std::initializer_list<const char*> types) {
    for (const char* one : types)
      if (t == one) return true;
    return false;
  };
  const bool rates = in(type, {"mirror", "phong", "blinn_phong"});
  const auto uses = [&](const std::string& key) {
    if (key == "reflection_rate" || key == "refraction_rate") return rates;
    if (key == "ior") return rates || in(type, {"dielectric", "rough_dielectric", "plastic"});
    if (key == "exponent" || key == "specular") return in(type, {"glossy", "phong", "blinn_phong"});
    if (key == "ambient" || key == "diffuse" || key == "attenuation")
      return in(type, {"phong", "blinn_phong"});
    if (key == "distribution" || key == "roughness" || key == "visible_normals")
      return in(type, {"rough_conductor", "rough_dielectric", "plastic"});
    // The rates' weighting and an interface's reflectance share the key: kept only
    // between models that read it the same way.
    if (key == "fresnel") return rates == in(old, {"mirror", "phong", "blinn_phong"});
    return kEvery.count(key) > 0;
  };
  json switched = json::object();
  for (auto it = material.begin(); it != material.end(); ++it)
    if (it.key() == "type")
      switched["type"] = type;
    else if (uses(it.key()))
      switched[it.key()] = it.value();
  return switched;
}

/// What a key means, for the keys a student may not know from their words (empty for
/// the others: the form then names the key's place in the file).
QString tipFor(const std::string& key) {
  if (key == "m" || key == "n")
    return PropertiesPanel::tr(
        "How finely the sphere is drawn in the 3D view: m bands from pole to pole, n slices "
        "around its axis (the rays still meet the exact sphere)");
  if (key == "diffuse")
    return PropertiesPanel::tr("Diffuse coefficient kd of the Phong model, in [0, 1]");
  if (key == "roughness")
    return PropertiesPanel::tr(
        "Roughness alpha: the width of the microfacet distribution (> 0, about the RMS slope "
        "of the microfacets)");
  if (key == "ior_outside")
    return PropertiesPanel::tr(
        "Index of refraction of the medium on the outer side of this surface (1 for air)");
  if (key == "ambient")
    return PropertiesPanel::tr(
        "Ambient coefficient times the ambient light, ka Ia (RGB, >= 0); the surface returns "
        "ambient times colour");
  if (key == "attenuation")
    return PropertiesPanel::tr(
        "Attenuation coefficients [c, l, q]: light falls off with distance d as "
        "1 / (c + l d + q d^2); [0, 0, 1] is the physical 1 / d^2, [1, 0, 0] no falloff");
  if (key == "visible_normals")
    return PropertiesPanel::tr(
        "Visible normal sampling: sample only the microfacet normals the viewer sees "
        "(Heitz 2018; GGX only)");
  if (key == "fresnel")
    return PropertiesPanel::tr(
        "Fresnel reflectance: exact (the Fresnel equations) or schlick (Schlick's "
        "approximation). For mirror, phong and blinn_phong: none keeps the constant reflection "
        "and refraction rates kr and kt; exact or schlick weighs the reflected ray kr R and the "
        "refracted ray kt (1 - R), R the reflectance at the hit");
  if (key == "priority")
    return PropertiesPanel::tr(
        "Nested media: 0, this surface names the media on its two sides (ior, ior outside); 1 "
        "or more, the object is a volume of index ior, and where volumes overlap the one of "
        "higher priority fills the overlap (a glass lens in water: glass 2, water 1)");
  if (key == "distribution")
    return PropertiesPanel::tr(
        "Microfacet distribution: ggx (Trowbridge-Reitz, long tails) or beckmann (Gaussian "
        "slopes)");
  if (key == "acceleration")
    return PropertiesPanel::tr(
        "How rays search the meshes: bvh (through their bounding volume hierarchy) or none "
        "(brute force, every triangle; the same image, slower)");
  if (key == "bvh_split")
    return PropertiesPanel::tr(
        "How the meshes' hierarchies split their boxes: sah (surface area heuristic) or median "
        "(half of the triangles on each side); the same image");
  if (key == "near_clip_shape")
    return PropertiesPanel::tr(
        "Where camera rays start, near clip away from the eye: on a plane in front of the eye "
        "(plane) or along each ray (sphere, as smallpt)");
  if (key == "normals")
    return PropertiesPanel::tr(
        "Shading normals of the mesh: file (the file's vertex normals, flat without them), "
        "flat (each triangle's own normal) or smooth (computed, with the crease angle)");
  if (key == "crease_angle")
    return PropertiesPanel::tr(
        "Crease angle in degrees [0, 180]: edges between faces whose normals differ by more "
        "stay sharp when the normals are smooth");
  if (key == "ray_offset")
    return PropertiesPanel::tr(
        "Ray offset: secondary and shadow rays start past the hit point's error bound; "
        "switched off, shadow acne appears");
  return {};
}

/// Words for a key ("vertical_fov" -> "vertical fov"), in the window's language
/// (SceneWords.h lists them for the translators); the sphere's one-letter `m` and `n` with
/// what they count.
QString label(const std::string& key) {
  if (key == "m") return PropertiesPanel::tr("m (bands from pole to pole)");
  if (key == "n") return PropertiesPanel::tr("n (slices around the axis)");
  QString text = QString::fromStdString(key);
  text.replace(QLatin1Char('_'), QLatin1Char(' '));
  return QCoreApplication::translate("SceneKeys", text.toUtf8().constData());
}

/// A value of a list ("raycast"), in the window's language. An algorithm's and a shape's
/// words come from the phrase table (`algorithm.<word>`, `shape.<word>`; an algorithm in
/// English is its word as the file writes it), the other values from Qt's translation
/// (SceneWords.h).
QString valueLabel(const char* value) {
  const Language language = uiLanguage();
  // The file's words that are not English words.
  if (language == Language::English) {
    const std::string word = value;
    if (word == "blinn_phong") return PropertiesPanel::tr("Blinn-Phong");
    if (word == "rough_conductor") return PropertiesPanel::tr("rough metal");
    if (word == "rough_dielectric") return PropertiesPanel::tr("rough glass");
  }
  if (parseAlgorithm(value))
    return language == Language::English
               ? QString::fromLatin1(value)
               : QString::fromStdString(phrase("algorithm." + std::string(value), language));
  const std::string shapeKey = "shape." + std::string(value);
  if (hasPhrase(shapeKey)) return QString::fromStdString(phrase(shapeKey, language));
  return QCoreApplication::translate("SceneValues", value);
}

bool isNumberTriple(const json& v) {
  return v.is_array() && v.size() == 3 && v[0].is_number() && v[1].is_number() && v[2].is_number();
}

QDoubleSpinBox* numberBox(double value) {
  auto* box = new QDoubleSpinBox;
  box->setRange(-1e6, 1e6);
  box->setDecimals(3);
  box->setMinimumWidth(40);
  box->setSingleStep(std::abs(value) >= 10.0 ? 1.0 : 0.1);
  box->setValue(value);
  box->setKeyboardTracking(false);
  return box;
}

}  // namespace

PropertiesPanel::PropertiesPanel(SceneDocument& document, QWidget* parent)
    : QWidget(parent), m_document(document) {
  m_layout = new QVBoxLayout(this);
  connect(&m_document, &SceneDocument::sceneChanged, this, [this] {
    if (m_object >= int(m_document.scene().objects.size())) m_object = -1;
    rebuild();
  });
  rebuild();
}

void PropertiesPanel::showObject(int object) {
  m_object = object >= 0 && object < int(m_document.scene().objects.size()) ? object : -1;
  rebuild();
}

QWidget* PropertiesPanel::field(const std::string& pointer) const {
  return m_form ? m_form->findChild<QWidget*>(QString::fromStdString(pointer)) : nullptr;
}

bool PropertiesPanel::setValue(const std::string& pointer, const std::string& jsonValue,
                               const QString& labelText) {
  const std::string origin = m_document.origin();
  const int mergeId = int(std::hash<std::string>{}(pointer)&0x3fffffff);
  try {
    m_document.apply(
        labelText,
        [&](const Scene& scene) { return edit::setValue(scene, pointer, jsonValue, origin); },
        mergeId);
    return true;
  } catch (const Exception& e) {
    emit editRefused(QString::fromStdString(e.what()));
    rebuild();  // show the value the scene still has
    return false;
  }
}

void PropertiesPanel::rebuild() {
  // The form is made anew after every change; a field that triggered the change must
  // not be deleted inside its own signal, so the old form goes later.
  if (m_form) {
    m_form->hide();
    m_form->deleteLater();
  }
  m_form = new QWidget;
  auto* layout = new QVBoxLayout(m_form);
  layout->setContentsMargins(0, 0, 0, 0);
  m_layout->addWidget(m_form);
  const Scene& scene = m_document.scene();
  if (m_object >= 0) {
    const SceneObject& o = scene.objects[std::size_t(m_object)];
    const std::string base = "/objects/" + std::to_string(m_object);
    addGroup(tr("Shape of %1").arg(QString::fromStdString(o.name)), base + "/shape");
    addTransformGroup(QString::fromStdString(o.name), base);
    // Which material, chosen among the scene's.
    auto* materialGroup = new QGroupBox(tr("Material"));
    auto* materialForm = new QFormLayout(materialGroup);
    auto* choice = new QComboBox;
    choice->setObjectName(QString::fromStdString(base + "/material"));
    choice->setToolTip(tr("The material this object is made of (shared with other objects)"));
    for (const Material& m : scene.materials) choice->addItem(QString::fromStdString(m.name));
    choice->setCurrentIndex(o.material);
    connect(choice, QOverload<int>::of(&QComboBox::activated), this, [this, base, choice](int) {
      setValue(base + "/material", json(choice->currentText().toStdString()).dump(),
               tr("Use material %1").arg(choice->currentText()));
    });
    materialForm->addRow(tr("uses"), choice);
    m_form->layout()->addWidget(materialGroup);
    addGroup(tr("Material %1")
                 .arg(QString::fromStdString(scene.materials[std::size_t(o.material)].name)),
             "/materials/" + std::to_string(o.material));
    auto* motion = new QGroupBox(tr("Motion over the shutter"));
    auto* motionForm = new QFormLayout(motion);
    auto* row = new QWidget;
    auto* rowLayout = new QHBoxLayout(row);
    rowLayout->setContentsMargins(0, 0, 0, 0);
    const std::string pointer = base + "/velocity";
    row->setObjectName(QString::fromStdString(pointer));
    for (int i = 0; i < 3; ++i) {
      auto* box = numberBox(o.velocity[i]);
      box->setToolTip(tr("Velocity, world units over the shutter interval (motion blur)"));
      rowLayout->addWidget(box);
      connect(box, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
              [this, pointer, row](double) {
                json v = json::array();
                for (auto* b : row->findChildren<QDoubleSpinBox*>()) v.push_back(b->value());
                setValue(pointer, v.dump(), tr("Set velocity"));
              });
    }
    motionForm->addRow(tr("velocity"), row);
    m_form->layout()->addWidget(motion);
  } else {
    addGroup(tr("Camera"), "/camera");
    addGroup(tr("Render settings"), "/render");
  }
  static_cast<QVBoxLayout*>(m_form->layout())->addStretch(1);
}

QWidget* PropertiesPanel::makeField(const std::string& key, const std::string& place,
                                    const nlohmann::ordered_json& value, bool material,
                                    const QString& undoText) {
  if (material && key == "type") {
    return makeMaterialTypeBox(place, value, undoText);
  } else if (kReadOnlyKeys.count(key) || value.is_object() ||
             (value.is_array() && !value.empty() && value[0].is_array() && key == "matrix")) {
    // A read-only word of the format (the shape's type) in the window's language.
    auto* text = new QLabel(!value.is_string() ? QString::fromStdString(value.dump())
                            : key == "type"    ? valueLabel(value.get<std::string>().c_str())
                                               : QString::fromStdString(value.get<std::string>()));
    text->setWordWrap(true);
    return text;
  } else if (value.is_boolean()) {
    auto* box = new QCheckBox;
    box->setChecked(value.get<bool>());
    connect(box, &QCheckBox::toggled, this,
            [this, place, undoText](bool on) { setValue(place, on ? "true" : "false", undoText); });
    return box;
  } else if (value.is_string() && kChoices.count(key)) {
    auto* box = new QComboBox;
    for (const char* c : kChoices.at(key)) box->addItem(valueLabel(c), QString::fromLatin1(c));
    box->setCurrentIndex(box->findData(QString::fromStdString(value.get<std::string>())));
    connect(box, QOverload<int>::of(&QComboBox::activated), this,
            [this, place, box, undoText](int) {
              setValue(place, json(box->currentData().toString().toStdString()).dump(), undoText);
            });
    return box;
  } else if (value.is_number() && kIntegerKeys.count(key)) {
    // Whole numbers only where the format wants them: a radius written 1 still takes 1.5.
    auto* box = new QSpinBox;
    box->setRange(-1000000000, 1000000000);
    box->setValue(value.get<int>());
    box->setKeyboardTracking(false);
    connect(box, QOverload<int>::of(&QSpinBox::valueChanged), this,
            [this, place, undoText](int v) { setValue(place, std::to_string(v), undoText); });
    return box;
  } else if (value.is_number()) {
    auto* box = numberBox(value.get<double>());
    connect(box, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
            [this, place, undoText](double v) { setValue(place, json(v).dump(), undoText); });
    return box;
  } else if (isNumberTriple(value) ||
             (value.is_array() && !value.empty() && isNumberTriple(value[0]))) {
    return makeVectorRows(key, place, value, undoText);
  } else {
    auto* text = new QLabel(QString::fromStdString(value.dump()));
    text->setWordWrap(true);
    return text;
  }
}

QWidget* PropertiesPanel::makeMaterialTypeBox(const std::string& place,
                                              const nlohmann::ordered_json& value,
                                              const QString& undoText) {
  // The scattering model: the form then shows that model's parameters.
  auto* box = new QComboBox;
  for (const char* type : kMaterialTypes) {
    box->addItem(valueLabel(type), QString::fromLatin1(type));
    box->setItemData(box->count() - 1, tr("\"%1\" in the scene file").arg(QLatin1String(type)),
                     Qt::ToolTipRole);
  }
  box->setCurrentIndex(box->findData(QString::fromStdString(value.get<std::string>())));
  box->setToolTip(
      tr("Scattering model: diffuse (Lambert), mirror (reflection and "
         "refraction rates), dielectric (Fresnel glass), glossy (Phong), phong (the classic "
         "Phong model: ambient, diffuse, specular), blinn_phong (Phong with Blinn's "
         "half-vector highlight), rough_conductor (microfacet metal), rough_dielectric "
         "(microfacet glass), plastic (a rough dielectric coating over a diffuse base)"));
  connect(box, QOverload<int>::of(&QComboBox::activated), this, [this, place, box, undoText](int) {
    // The whole material at once: the new model's parameters only.
    const std::string type = box->currentData().toString().toStdString();
    const std::string material = place.substr(0, place.rfind('/'));
    const json now = json::parse(edit::valueAt(m_document.scene(), material, m_document.origin()));
    if (now.value("type", "diffuse") != type)
      setValue(material, switchedMaterial(now, type).dump(), undoText);
  });
  return box;
}

QWidget* PropertiesPanel::makeVectorRows(const std::string& key, const std::string& place,
                                         const nlohmann::ordered_json& value,
                                         const QString& undoText) {
  // A vector (or a list of vectors: axes, vertices): one row of three per vector.
  const bool list = !isNumberTriple(value);
  auto* rows = new QWidget;
  auto* rowsLayout = new QVBoxLayout(rows);
  rowsLayout->setContentsMargins(0, 0, 0, 0);
  const auto commit = [this, place, rows, list, undoText] {
    json v = json::array();
    for (auto* row : rows->findChildren<QWidget*>(QStringLiteral("row"))) {
      json triple = json::array();
      for (auto* b : row->findChildren<QDoubleSpinBox*>()) triple.push_back(b->value());
      v.push_back(triple);
    }
    setValue(place, (list ? v : v[0]).dump(), undoText);
  };
  const std::size_t count = list ? value.size() : 1;
  for (std::size_t r = 0; r < count; ++r) {
    const json& triple = list ? value[r] : value;
    auto* row = new QWidget;
    row->setObjectName(QStringLiteral("row"));
    auto* rowLayout = new QHBoxLayout(row);
    rowLayout->setContentsMargins(0, 0, 0, 0);
    for (int i = 0; i < 3; ++i) {
      auto* box = numberBox(triple[std::size_t(i)].get<double>());
      rowLayout->addWidget(box);
      connect(box, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
              [commit](double) { commit(); });
    }
    if (key == "colour" || key == "colour2" || key == "background")
      rowLayout->addWidget(makeColourButton(place, triple, undoText));
    rowsLayout->addWidget(row);
  }
  return rows;
}

QPushButton* PropertiesPanel::makeColourButton(const std::string& place,
                                               const nlohmann::ordered_json& triple,
                                               const QString& undoText) {
  // Linear RGB in [0, 1], picked as a colour.
  auto* pick = new QPushButton(tr("…"));
  pick->setToolTip(tr("Choose the colour"));
  pick->setMaximumWidth(32);
  const QColor shown = QColor::fromRgbF(std::clamp(triple[0].get<double>(), 0.0, 1.0),
                                        std::clamp(triple[1].get<double>(), 0.0, 1.0),
                                        std::clamp(triple[2].get<double>(), 0.0, 1.0));
  pick->setStyleSheet(QStringLiteral("background-color: %1").arg(shown.name()));
  connect(pick, &QPushButton::clicked, this, [this, place, shown, undoText] {
    const QColor c = QColorDialog::getColor(shown, this, tr("Colour"));
    if (c.isValid())
      setValue(place, json::array({c.redF(), c.greenF(), c.blueF()}).dump(), undoText);
  });
  return pick;
}

void PropertiesPanel::addTransformGroup(const QString& object, const std::string& base) {
  json steps;
  try {
    steps =
        json::parse(edit::valueAt(m_document.scene(), base + "/transform", m_document.origin()));
  } catch (const std::exception&) {
    return;  // no steps: the shape's values are where it is
  }
  if (!steps.is_array() || steps.empty()) return;
  const QString title = tr("Transform of %1").arg(object);
  auto* group = new QGroupBox(title);
  group->setToolTip(
      tr("The steps the scene file applies to the shape, in order: the shape's "
         "values above are the ones before them"));
  auto* form = new QFormLayout(group);
  for (std::size_t i = 0; i < steps.size(); ++i) {
    if (!steps[i].is_object() || steps[i].size() != 1) continue;
    const std::string kind = steps[i].begin().key();
    const json& value = steps[i].begin().value();
    const std::string place = base + "/transform/" + std::to_string(i) + "/" + kind;
    const QString name = QStringLiteral("%1. %2").arg(i + 1).arg(label(kind));
    const QString undoText = tr("Set %1 of %2").arg(name, title);
    // A rotation's axis and angle each on a row; other steps one value.
    std::vector<std::pair<std::string, const json*>> parts;
    if (kind == "rotate" && value.is_object()) {
      for (auto it = value.begin(); it != value.end(); ++it)
        parts.emplace_back(it.key(), &it.value());
    } else {
      parts.emplace_back(kind, &value);
    }
    for (const auto& [key, part] : parts) {
      const std::string at = key == kind ? place : place + "/" + key;
      QWidget* widget = makeField(key, at, *part, false, undoText);
      widget->setObjectName(QString::fromStdString(at));
      widget->setToolTip(
          tr("%1 (%2 in the scene file)").arg(label(key), QString::fromStdString(at)));
      form->addRow(key == kind ? name : name + QStringLiteral(" ") + label(key), widget);
    }
  }
  m_form->layout()->addWidget(group);
}

void PropertiesPanel::addGroup(const QString& title, const std::string& pointer) {
  json values;
  try {
    values = json::parse(edit::valueAt(m_document.scene(), pointer, m_document.origin()));
  } catch (const std::exception&) {
    return;
  }
  auto* group = new QGroupBox(title);
  auto* form = new QFormLayout(group);
  const bool material = pointer.rfind("/materials/", 0) == 0;
  // Keys the file leaves out at their default, shown all the same: the index outside a
  // refracting surface (after its ior), the render block's ray offset and the shape of a
  // camera's near clip.
  if (material && values.contains("ior") && !values.contains("ior_outside")) {
    json withOutside = json::object();
    for (auto it = values.begin(); it != values.end(); ++it) {
      withOutside[it.key()] = it.value();
      if (it.key() == "ior") withOutside["ior_outside"] = 1.0;
    }
    values = std::move(withOutside);
  }
  // The rates' Fresnel weighting of a mirror or a classic material ("none"), and the
  // nesting priority of glass (0).
  const std::string type = material ? values.value("type", "diffuse") : "";
  if ((type == "mirror" || type == "phong" || type == "blinn_phong") && !values.contains("fresnel"))
    values["fresnel"] = "none";
  if ((type == "dielectric" || type == "rough_dielectric") && !values.contains("priority"))
    values["priority"] = 0;
  if (pointer == "/render" && !values.contains("ray_offset")) values["ray_offset"] = true;
  if (pointer == "/render" && !values.contains("acceleration")) values["acceleration"] = "bvh";
  if (pointer == "/render" && !values.contains("bvh_split")) values["bvh_split"] = "sah";
  if (pointer == "/camera" && values.contains("near_clip") && !values.contains("near_clip_shape"))
    values["near_clip_shape"] = "plane";
  // A mesh's normals, "file" when the file leaves them out.
  if (values.value("type", "") == "mesh" && !values.contains("normals")) values["normals"] = "file";
  for (auto it = values.begin(); it != values.end(); ++it) {
    const std::string key = it.key();
    if (material && key == "texture") continue;  // addTextureRows, after the colour
    const std::string place = pointer + "/" + key;
    const json& value = it.value();
    const QString what = label(key);
    const QString undoText = tr("Set %1 of %2").arg(what, title);
    QWidget* widget = makeField(key, place, value, material, undoText);
    widget->setObjectName(QString::fromStdString(place));
    if (widget->toolTip().isEmpty()) widget->setToolTip(tipFor(key));
    if (widget->toolTip().isEmpty())
      widget->setToolTip(tr("%1 (%2 in the scene file)").arg(what, QString::fromStdString(place)));
    form->addRow(what, widget);
    if (material && key == "colour") addTextureRows(form, pointer, values, title);
  }
  m_form->layout()->addWidget(group);
}

void PropertiesPanel::addTextureRows(QFormLayout* form, const std::string& pointer,
                                     const json& material, const QString& title) {
  const std::string place = pointer + "/texture";
  const bool on = material.contains("texture") && material["texture"].is_object();
  auto* box = new QCheckBox;
  box->setObjectName(QString::fromStdString(place));
  box->setChecked(on);
  box->setToolTip(
      tr("A solid checker on the colour: space is cut into cubes of side \"checker scale\", "
         "which take the colour and the second colour in turn (for depth of field and "
         "aliasing)"));
  const QString undoText = tr("Set %1 of %2").arg(tr("checker texture"), title);
  connect(box, &QCheckBox::toggled, this, [this, pointer, place, undoText](bool checked) {
    if (checked) {
      const json checker = {{"type", "checker"}, {"scale", 1.0}, {"colour2", {0.1, 0.1, 0.1}}};
      setValue(place, checker.dump(), undoText);
    } else {
      // Off: the material as it is, without its "texture" key.
      json plain = json::parse(edit::valueAt(m_document.scene(), pointer, m_document.origin()));
      plain.erase("texture");
      setValue(pointer, plain.dump(), undoText);
    }
  });
  form->addRow(tr("checker texture"), box);
  if (!on) return;
  const json& texture = material["texture"];
  const std::pair<const char*, QString> rows[] = {{"scale", tr("checker scale")},
                                                  {"colour2", tr("second colour")}};
  for (const auto& [key, words] : rows) {
    if (!texture.contains(key)) continue;
    const std::string at = place + "/" + key;
    QWidget* widget = makeField(key, at, texture[key], true, tr("Set %1 of %2").arg(words, title));
    widget->setObjectName(QString::fromStdString(at));
    widget->setToolTip(std::string(key) == "scale"
                           ? tr("Side of a checker cube, world units (> 0)")
                           : tr("The colour of every other checker cube, linear RGB in [0, 1]"));
    form->addRow(words, widget);
  }
}

}  // namespace raylab::app
