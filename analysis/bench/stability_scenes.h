// What the stability sweeps render: cages built to push one condition each
// (a grazing plane, poles of any valence, creased edges), the environments
// that light them, and a metal.
#pragma once

#include <glm/vec3.hpp>

#include "materials/material.h"
#include "scenes/scene.h"

namespace facet::analysis::bench::stability {

// A flat open grid in the xz plane, normal +y, 8 x 8 quads over [-6, 6]^2.
scene::ControlCage planeCage();

// A closed quad cage with two poles of valence n on the unit sphere (at
// +-y); between them two rings of 2n vertices, whose alternate vertices are
// valence 3 for every n, so only the poles change along the sweep.
scene::ControlCage poleCage(int n);

// The unit cube cage with the loop of its four top edges creased.
scene::ControlCage creasedCube(double sharpness);

scene::ControlCage cubeCage();

scene::Environment environmentOf(scene::EnvironmentMap map);

// A constant sky of radiance 1 with a 2 x 2 texel sun of radiance `sun`,
// 31 degrees above the horizon, on the camera's side.
scene::EnvironmentMap sunEnvironment(double sun);

materials::Material metal(double alpha, const glm::dvec3& f0);

}  // namespace facet::analysis::bench::stability
