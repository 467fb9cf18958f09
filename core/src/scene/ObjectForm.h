#pragma once

#include "raylab/core/Scene.h"

#include <string>

namespace raylab::detail {

/// The writer's own form of built-in shape object `o` of `scene` (JSON text): its shape as
/// it now is, any transform baked in. SceneReader keeps it beside the file's entry
/// (SceneObject::FileForm); SceneWriter writes the file's entry while the two agree.
std::string bakedObjectForm(const SceneObject& o, const Scene& scene);

}  // namespace raylab::detail
