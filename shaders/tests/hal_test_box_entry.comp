// hal_test_box_entry.comp: the software traversal's ray/box test (common/trace.glsl box_entry) on
// given rays and boxes, so that tests can check its miss value at every tmax the tracer uses.
#version 460
#extension GL_GOOGLE_include_directive : require
#define TRACE_SOFTWARE
#include "common/compute.glsl"
#include "common/scene_data.glsl"

layout(local_size_x = 64) in;

layout(set = 0, binding = 0) uniform Params {
  uint count;
  uint pad0;
  uint pad1;
  uint pad2;
} params;
// Per case, four vec4s: (origin, tmin), (direction, tmax), (box min, 0), (box max, 0).
layout(set = 0, binding = 1, std430) readonly buffer Cases { vec4 values[]; } cases;
layout(set = 0, binding = 2, std430) writeonly buffer Entries { float values[]; } entries;
// What trace.glsl's software variant reads; unused here.
layout(set = 0, binding = 3, std430) readonly buffer BvhNodes { BvhNode values[]; } bvh_nodes;
layout(set = 0, binding = 4, std430) readonly buffer BvhTriangles { uint values[]; } bvh_triangles;
layout(set = 0, binding = 5, std430) readonly buffer Triangles { Triangle values[]; } triangles;
layout(set = 0, binding = 6, std430) readonly buffer Lights { Light values[]; } lights;

#include "common/trace.glsl"

void main() {
  uint i = invocation_index();
  if (i >= params.count) return;
  vec4 o = cases.values[4u * i], d = cases.values[4u * i + 1u];
  entries.values[i] =
      box_entry(o.xyz, safe_inverse(d.xyz), cases.values[4u * i + 2u].xyz, cases.values[4u * i + 3u].xyz, o.w, d.w);
}
