// What a public facet::Scene holds: the engine's validated scene.
#pragma once

#include "facet/scene.h"
#include "scenes/scene.h"

namespace facet::v0::detail {

struct SceneData {
  scene::Scene scene;
};

}  // namespace facet::v0::detail
