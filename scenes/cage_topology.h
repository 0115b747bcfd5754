// What a control cage's faces close into, read from its indices and
// positions alone: the facts the light-transport choice and the paths'
// shading rest on (docs/rendering.md, "Scenes whose paths cannot continue"
// and "Transmission and absorption").
#pragma once

#include "scenes/control_cage.h"

namespace facet::scene {

// Whether the cage's faces close into one oriented surface with a sphere's
// topology: no holes, no face repeating a vertex, every directed edge once
// and its reverse once (so every edge borders two faces, oriented alike),
// the faces connected through their edges, and V - E + F = 2 (which, with
// the faces connected, also excludes pinched vertices).
bool closesIntoSphere(const ControlCage& cage);

// Whether the cage's faces bound solids, each wound counter-clockwise seen
// from outside: no holes, no face repeating a vertex, every directed edge
// once and its reverse once, and every connected piece of faces enclosing a
// positive signed volume (any genus). Its Catmull-Clark limit surface, and
// its polygons as authored, are then closed: a ray from inside crosses the
// surface before it reaches anything outside.
bool enclosesSolid(const ControlCage& cage);

}  // namespace facet::scene
