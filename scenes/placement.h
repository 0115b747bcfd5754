// Where objects stand: a cage moved by an affine transform, and a scene's
// model turned about the vertical for a turntable (docs/preview-stage.md,
// "Turntables").
#pragma once

#include <glm/mat4x4.hpp>

#include "scenes/control_cage.h"
#include "scenes/scene.h"

namespace facet::scene {

// Both subdivision schemes are affine invariant, so transforming the cage
// transforms the limit surface exactly. Authored normals take the inverse
// transpose; a mirroring transform reverses every face's winding, and each
// corner's attributes with it, so that faces keep facing outwards.
void transformCage(ControlCage& cage, const glm::dmat4& matrix);

// What a turntable turns: the model under fixed camera, lights and
// environment, or the environment map about a fixed model and camera.
enum class TurntableTurn { Model, Environment };

// Frame `frame` of an n-frame turntable: the model (every object) or the
// environment turned by 2πf/n about the vertical (+y, the environment's and
// the ground's up) through the camera's target. Throws std::invalid_argument
// where the turn is Environment and the scene has no environment map.
Scene turntableFrame(const Scene& scene, int frame, int frames, TurntableTurn turn);

}  // namespace facet::scene
