#include "ExportRole.h"

#include <vtkInformation.h>
#include <vtkInformationStringKey.h>
#include <vtkNew.h>
#include <vtkProp.h>

namespace raylab::vis {

namespace {

vtkInformationStringKey* roleKey() {
  // Owned by VTK's key registry for the program's life.
  static vtkInformationStringKey* key = new vtkInformationStringKey("RAYLAB_ROLE", "raylab");
  return key;
}

}  // namespace

void setExportRole(vtkProp* prop, const std::string& role) {
  if (!prop) return;
  if (!prop->GetPropertyKeys()) {
    vtkNew<vtkInformation> keys;
    prop->SetPropertyKeys(keys);
  }
  prop->GetPropertyKeys()->Set(roleKey(), role.c_str());
}

std::string exportRole(vtkProp* prop) {
  vtkInformation* keys = prop ? prop->GetPropertyKeys() : nullptr;
  if (!keys || !keys->Has(roleKey())) return {};
  return keys->Get(roleKey());
}

}  // namespace raylab::vis
