#pragma once

#include <QString>
#include <QWidget>

#include <nlohmann/json_fwd.hpp>

#include <string>

class QFormLayout;
class QPushButton;
class QVBoxLayout;

namespace raylab::app {

class SceneDocument;

/**
 * \brief Every value of the selection that a scene file holds, editable: with an object
 * selected, its shape's parameters (centre, radius, size, axes, the sphere's m and n
 * tessellation, corners and edges), its motion and its material (type and every
 * parameter of that type, colours with a colour picker, and its checker texture); with
 * nothing selected, the
 * camera (position, look-at, up, field of view, image size, thin lens) and the render
 * settings (algorithm, spp, max depth, seed, ...). The original course program had to
 * change material parameters in its source code.
 *
 * The form is made from the scene's file form (edit::valueAt), so it shows exactly the
 * keys a file would hold; each value entered becomes edit::setValue of its JSON place,
 * one undo step (repeated changes of one value merge), checked by the loader's rules: a
 * refused value is reported with the loader's message (editRefused) and nothing changes.
 */
class PropertiesPanel : public QWidget {
  Q_OBJECT

 public:
  explicit PropertiesPanel(SceneDocument& document, QWidget* parent = nullptr);

  /// Shows object `object`'s values (-1: the camera and render settings).
  void showObject(int object);
  int object() const { return m_object; }

  /// Sets the value at JSON place `pointer` to `jsonValue` as the form's fields do
  /// (for tests and scripts). Returns false when the value was refused.
  bool setValue(const std::string& pointer, const std::string& jsonValue, const QString& label);

  /// The field editing JSON place `pointer` (a widget whose objectName is the pointer),
  /// null when the form has none.
  QWidget* field(const std::string& pointer) const;

 signals:
  /// A value was refused; `message` is the loader's whole message.
  void editRefused(const QString& message);

 private:
  /// Makes the form again from the scene (after any change).
  void rebuild();
  void addGroup(const QString& title, const std::string& pointer);
  /// The material at `pointer`'s checker texture (Texture.h): a check box that adds or
  /// removes it and, when it is on, its cube side and second colour.
  void addTextureRows(QFormLayout* form, const std::string& pointer,
                      const nlohmann::ordered_json& material, const QString& title);
  /// The object's transform steps as the file lists them (applied in order after the shape,
  /// whose values are the ones before them): each step's values editable in place.
  void addTransformGroup(const QString& object, const std::string& base);
  /// The widget that edits the value `value` of `key` at JSON place `place` (a label when
  /// it is not edited here); `material` when the key belongs to a material.
  QWidget* makeField(const std::string& key, const std::string& place,
                     const nlohmann::ordered_json& value, bool material, const QString& undoText);

  /// makeField's parts: the material's scattering model (its form then shows that model's
  /// parameters); a vector or a list of vectors, one row of three per vector; the button
  /// that picks a colour (linear RGB in [0, 1]) for the vector `triple`.
  QWidget* makeMaterialTypeBox(const std::string& place, const nlohmann::ordered_json& value,
                               const QString& undoText);
  QWidget* makeVectorRows(const std::string& key, const std::string& place,
                          const nlohmann::ordered_json& value, const QString& undoText);
  QPushButton* makeColourButton(const std::string& place, const nlohmann::ordered_json& triple,
                                const QString& undoText);

  SceneDocument& m_document;
  int m_object = -1;
  QWidget* m_form = nullptr;
  QVBoxLayout* m_layout = nullptr;
  bool m_rebuildQueued = false;
};

}  // namespace raylab::app
