// bandwidth_copy: copies one storage buffer into another, 16 bytes a load and a store, striding
// over the whole buffer: `asvgf bench` times it to measure the memory bandwidth its floors use
// (the way the frame's passes move memory, which a transfer-queue copy need not match).
#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/compute.glsl"

layout(local_size_x = 256) in;

layout(set = 0, binding = 0, std140) uniform Params {
  uint count;   // 16-byte elements to copy
  uint stride;  // invocations in the whole dispatch
} params;
layout(set = 0, binding = 1, std430) readonly buffer Source { uvec4 values[]; } src;
layout(set = 0, binding = 2, std430) writeonly buffer Destination { uvec4 values[]; } dst;

void main() {
  for (uint i = invocation_index(); i < params.count; i += params.stride) dst.values[i] = src.values[i];
}
