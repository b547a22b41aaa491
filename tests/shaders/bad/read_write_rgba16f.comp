// Breaks a portability rule: an rgba16f storage image both read and written (WGSL and ESSL 310
// allow read-write storage images only in r32 formats).
#version 460
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, rgba16f) uniform image2D color;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  imageStore(color, p, imageLoad(color, p) * 0.5);
}
