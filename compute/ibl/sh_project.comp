// Per row of the map, its radiance summed with the weights of the five
// azimuthal integrals of sh_column_integrals; the host multiplies each row
// by its polar integrals in double and adds the rows up
// (engine/ibl/prefilter_steps.h, shFromRowSums).
#version 460
#extension GL_GOOGLE_include_directive : require

#include "rules/language.glsl"
#include "rules/environment/spherical_harmonics.h"
#include "rules/grid/config.h"

layout(local_size_x = FACET_WORKGROUP_SIZE) in;

layout(set = 0, binding = 0, std140) uniform Params {
  int width;
  int height;
};
layout(set = 0, binding = 1, std430) readonly buffer Map { float map[]; };
layout(set = 0, binding = 2, std430) writeonly buffer RowSums { vec4 rowSums[]; };  // 5 per row, rgb in xyz

void main() {
  int y = int(gl_GlobalInvocationID.x);
  if (y >= height) return;
  vec3 one = vec3(0.0);
  vec3 sinPhi = vec3(0.0);
  vec3 cosPhi = vec3(0.0);
  vec3 cos2Phi = vec3(0.0);
  vec3 sinCosPhi = vec3(0.0);
  for (int x = 0; x < width; ++x) {
    uint i = 3u * uint(y * width + x);
    vec3 radiance = vec3(map[i], map[i + 1u], map[i + 2u]);
    ShColumnIntegrals c = sh_column_integrals(x, width);
    one += c.one * radiance;
    sinPhi += c.sin_phi * radiance;
    cosPhi += c.cos_phi * radiance;
    cos2Phi += c.cos2_phi * radiance;
    sinCosPhi += c.sin_cos_phi * radiance;
  }
  uint o = 5u * uint(y);
  rowSums[o] = vec4(one, 0.0);
  rowSums[o + 1u] = vec4(sinPhi, 0.0);
  rowSums[o + 2u] = vec4(cosPhi, 0.0);
  rowSums[o + 3u] = vec4(cos2Phi, 0.0);
  rowSums[o + 4u] = vec4(sinCosPhi, 0.0);
}
