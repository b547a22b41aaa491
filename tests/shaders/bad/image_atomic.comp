// Breaks a portability rule: an image atomic (WebGPU has none).
#version 460
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, r32ui) uniform uimage2D counts;

void main() { imageAtomicAdd(counts, ivec2(gl_GlobalInvocationID.xy), 1u); }
