#pragma once
// Reads OBJ control cages in the convention of OpenSubdiv's regression shapes:
//
//   v x y z [w]                 vertex position (w is ignored)
//   vt u v [w]                  texture coordinate (w is ignored)
//   vn x y z                    accepted; indices in faces are range-checked
//   f a b c ...                 polygon of 3 or more vertices; each corner is
//                               v, v/vt, v//vn or v/vt/vn, 1-based or negative;
//                               vt indices on every corner or on none
//   t <name> <ni>/<nf>/<ns> <ints...> <floats...> <strings...>
//       crease     vertex pairs (0-based) + one sharpness, or one per pair
//       corner     vertices (0-based) + one sharpness, or one per vertex
//       hole       face indices (0-based)
//       interpolateboundary            0 none, 1 edge and corner, 2 edge only
//       facevaryinginterpolateboundary 0..5 (OpenSubdiv's FVarLinearInterpolation)
//       facevaryingpropagatecorners    0 or 1: CornersPlus1 or CornersPlus2
//                                      where the rule is one of those two
//       creasemethod   "normal" or "chaikin"
//       smoothtriangles "catmark" or "smooth"
//   s, g, o, usemtl, mtllib, l, p   accepted and ignored; '#' starts a comment
//
// Anything else — a malformed line, an index out of range, a non-finite
// coordinate, a face of fewer than 3 vertices — throws InputError naming
// file, line and rule. What OpenSubdiv subdivides is accepted: non-manifold
// edges and vertices, a vertex repeated within a face, vertices no face uses.

#include "scenes/control_cage.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace facet::scene {

ControlCage loadObjCage(const std::filesystem::path& path);

// `source` names the text in error messages (a file name, or a test label).
ControlCage parseObjCage(std::string_view text, const std::string& source);

}  // namespace facet::scene
