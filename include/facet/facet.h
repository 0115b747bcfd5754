// facet's public C++ API (docs/api.md): scenes, rendering, the preview stage, parity, BRDFs.
// Every function reports failure by throwing facet::Error. The names live in
// facet::v0, brought into facet as OpenSubdiv does with its version
// namespace, so that an incompatible API can later live beside this one;
// libfacet's own sources (FACET_IMPLEMENTATION) leave facet:: to the engine.
#pragma once

#include "facet/brdf.h"
#include "facet/error.h"
#include "facet/image.h"
#include "facet/output.h"
#include "facet/preview.h"
#include "facet/render.h"
#include "facet/scene.h"
#include "facet/version.h"
#include "facet/watch.h"
