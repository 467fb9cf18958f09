#pragma once

// What each prop of SceneView's renderer is, for the web export (ViewExport.cpp): a string
// kept in the prop's property keys ("object:3", "camera", "rays", ...). Private to vis.

#include <string>

class vtkProp;

namespace raylab::vis {

/// Tags `prop` with `role` (kept through any number of renders).
void setExportRole(vtkProp* prop, const std::string& role);
/// The role `prop` was tagged with, "" when none.
std::string exportRole(vtkProp* prop);

}  // namespace raylab::vis
