// The surface kernel's FEATURES specialization constant: which of its
// features a scene uses (scenes/scene_features.h, and the environment's
// options), one bit each, so that a scene pays for none it does not use and
// a kernel variant is named by one number. Valid GLSL and C++ (the subset of
// compute/layout/raycast_layout.h).
#ifndef FACET_LAYOUT_SURFACE_FEATURES_H
#define FACET_LAYOUT_SURFACE_FEATURES_H

// The bit of each feature.
const int FACET_FEATURE_OCCLUSION = 0;            // the environment's shadow rays (sampled, filtered)
const int FACET_FEATURE_ENVIRONMENT_SAMPLES = 1;  // filtered: the environment technique too
const int FACET_FEATURE_TEXTURES = 2;             // materials read textures or vertex colours per hit
const int FACET_FEATURE_EMISSION = 3;             // each ray's last slot holds emission
const int FACET_FEATURE_COMPENSATION = 4;         // some specular lobe is energy-compensated
const int FACET_FEATURE_PATHS = 5;                // the kernel shades path vertices and writes their state
const int FACET_FEATURE_TRANSMISSION = 6;         // materials transmit; paths carry their medium
const int FACET_FEATURE_LOBE_LIMITS = 7;          // paths count their continuations per lobe kind
const int FACET_FEATURE_ANISOTROPY = 8;           // hits evaluate the tangent field
const int FACET_FEATURE_CLEARCOAT = 9;
const int FACET_FEATURE_SHEEN = 10;
const int FACET_FEATURE_CHANNELS = 11;  // vertex colours or a second set of texture coordinates
const int FACET_FEATURE_SHADOW_CATCHER = 12;  // an object catches shadows for the paths (FACET_OBJECT_SHADOW_CATCHER)
const int FACET_FEATURE_HOLDOUT = 13;         // an object is black to camera rays (FACET_OBJECT_HOLDOUT)
const int FACET_FEATURE_IRIDESCENCE = 14;     // a material's Fresnel has a thin film

#endif
