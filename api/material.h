// A public Material validated into the engine's, errors naming `where`.
#pragma once

#include <string>

#include "facet/scene.h"
#include "materials/material.h"

namespace facet::api {

materials::Material toEngineMaterial(const v0::Material& material, const std::string& where);

}  // namespace facet::api
