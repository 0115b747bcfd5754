// A public Material validated into the engine's, errors naming `where`.
#pragma once

#include <string>

#include "facet/scene.h"
#include "materials/material.h"

namespace facet::v0::detail {

materials::Material toEngineMaterial(const Material& material, const std::string& where);

}  // namespace facet::v0::detail
