#version 450
// A uniform block of fixed size, and a storage block with a fixed header
// before its runtime array: reflection must know both minimum sizes.
layout(local_size_x = 1) in;
layout(std140, binding = 0) uniform Params { mat4 transform; vec4 tint; } params;
layout(std430, binding = 1) buffer Output { vec4 header[4]; float tail[]; } outputs;

void main() {
  outputs.header[0] = params.transform * params.tint;
  outputs.tail[0] = params.tint.w;
}
