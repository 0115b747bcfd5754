// The GLSL side of the language the rules are written in (rules/language.h
// states the subset and is the C++ side). A kernel includes this file and
// then the rules it calls itself, in any order, since each rule includes the
// rules it uses:
//   #extension GL_GOOGLE_include_directive : require
//   #include "rules/language.glsl"
//   #include "rules/shading/brdf.h"
//   ...
// (glslang -I<repo root>).
#ifndef FACET_RULES_LANGUAGE_GLSL
#define FACET_RULES_LANGUAGE_GLSL

#define real float
#define FACET_FN
#define FACET_OUT(type) out type
#define FACET_PRECISE precise

#endif
