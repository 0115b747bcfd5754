// The GLSL side of the language the rules are written in (rules/language.h
// states the subset and is the C++ side). A kernel includes this file before
// any rule:
//   #extension GL_GOOGLE_include_directive : require
//   #include "rules/language.glsl"
//   #include "rules/math.h"
//   ...
// (glslang -I<repo root>); rules/instance.h lists the order rules depend on.
#ifndef FACET_RULES_LANGUAGE_GLSL
#define FACET_RULES_LANGUAGE_GLSL

#define real float
#define FACET_FN
#define FACET_OUT(type) out type

#endif
