// interop_noisy_gradient.comp: the interop test's "renderer": a horizontal ramp (x / width) with
// deterministic per-pixel noise of +-0.25 (a hash of the pixel and frame), written into an image
// the test program created with raw Vulkan. Dispatched by that program, not through the HAL.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/compute.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, rgba32f) writeonly uniform image2D noisy;

uint hash(uint x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

void main() {
  ivec2 p = invocation_pixel();
  ivec2 size = imageSize(noisy);
  if (p.x >= size.x || p.y >= size.y) return;
  float ramp = (float(p.x) + 0.5) / float(size.x);
  float noise = (float(hash(uint(p.y * size.x + p.x) * 9781u + 7u) & 0xffffu) / 65535.0 - 0.5) * 0.5;
  imageStore(noisy, p, vec4(vec3(ramp + noise), 1.0));
}
