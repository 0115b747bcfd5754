// A finer control cage of the same limit surface, for ray-casting
// benchmarks that need many more patches than the cages on disk have.
#pragma once

#include "scenes/control_cage.h"

namespace facet::benchmarks {

// The cage `levels` uniform Catmull-Clark steps finer than `cage`, as a new
// control cage (the same limit surface). Creases and corners are not carried
// over (the cages refined here have none); holes neither.
scene::ControlCage refineUniformly(const scene::ControlCage& cage, int levels);

}  // namespace facet::benchmarks
