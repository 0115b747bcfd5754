#version 450
// A row-major matrix: 4 rows of vec2 at an 8-byte stride make the block 32
// bytes, where 2 columns at that stride would wrongly make it 16.
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer Transform { layout(row_major) mat2x4 transform; };

void main() { transform[0][0] = 1.0; }
