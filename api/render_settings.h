// The public RenderSettings applied to a scene, checked as the scene file's
// fields are: what Renderer::render renders and what writeExr describes.
#pragma once

#include "facet/render.h"
#include "scenes/scene.h"

namespace facet::v0 {

// Throws scene::InputError ("render settings: <field>: <rule>").
scene::Scene withSettings(const Scene& input, const RenderSettings& settings);

}  // namespace facet::v0
