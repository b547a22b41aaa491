// A uniform block with what the generated C++ struct must mirror: a nested struct used twice,
// vectors of each scalar type, and std140 gaps (a float followed by a vec4, a vec3 by a vec2).
#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/compute.glsl"

layout(local_size_x = 64) in;

struct Frame {
  vec4 origin;
  uvec2 size;
};

layout(set = 0, binding = 0, std140) uniform Params {
  float weight;
  vec4 tint;
  Frame current;
  Frame previous;
  vec3 axis;
  vec2 jitter;
  ivec3 offset;
  uint count;
} params;
layout(set = 0, binding = 1) writeonly buffer Output { vec4 values[]; } dst;

void main() {
  uint i = invocation_index();
  if (i >= params.count) return;
  dst.values[i] = params.tint * params.weight + params.current.origin - params.previous.origin +
                  vec4(params.axis, params.jitter.x) + vec4(params.offset, params.current.size.x + params.previous.size.y);
}
