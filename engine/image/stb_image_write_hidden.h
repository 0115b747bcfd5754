// stb_image_write, its functions hidden from the dynamic symbol table: a
// shared library that links Debian's stb (tinygltf does) must bind to its
// own copy, never to facet's.
#pragma once

#define STBIWDEF extern "C" __attribute__((visibility("hidden")))
#include <stb_image_write.h>
