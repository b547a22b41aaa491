// hal_test_scale.comp: dst[i] = src[i] * scale + offset. Used by the Vulkan backend's tests.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/compute.glsl"

layout(local_size_x = 64) in;

layout(set = 0, binding = 0) uniform Params {
  uint count;
  float scale;
  float offset;
} params;
layout(set = 0, binding = 1) readonly buffer Input { float values[]; } src;
layout(set = 0, binding = 2) writeonly buffer Output { float values[]; } dst;

void main() {
  uint i = invocation_index();
  if (i < params.count) dst.values[i] = src.values[i] * params.scale + params.offset;
}
