// hal_test_ray_query.comp: one ray per invocation against `scene`, committed hit written out.
// Used by the Vulkan backend's tests. The `rayquery` variant defines TRACE_RAY_QUERY; without it
// the shader only clears the hits (there is no software path to test here).
#version 460
#extension GL_GOOGLE_include_directive : require
#ifdef TRACE_RAY_QUERY
#extension GL_EXT_ray_query : require
#endif
#include "common/compute.glsl"

layout(local_size_x = 64) in;

layout(set = 0, binding = 0) uniform Params { uint count; } params;
#ifdef TRACE_RAY_QUERY
layout(set = 0, binding = 1) uniform accelerationStructureEXT scene;
#endif
// Two vec4 per ray: origin.xyz + tmin, direction.xyz + tmax.
layout(set = 0, binding = 2) readonly buffer Rays { vec4 values[]; } rays;
// Per ray: instance custom index, primitive index, floatBitsToUint(t), 1 if hit else 0.
layout(set = 0, binding = 3) writeonly buffer Hits { uvec4 values[]; } hits;

void main() {
  uint i = invocation_index();
  if (i >= params.count) return;
  vec4 origin = rays.values[2 * i];
  vec4 direction = rays.values[2 * i + 1];
  uvec4 hit = uvec4(0u);
#ifdef TRACE_RAY_QUERY
  rayQueryEXT query;
  rayQueryInitializeEXT(query, scene, gl_RayFlagsOpaqueEXT, 0xFF, origin.xyz, origin.w, direction.xyz, direction.w);
  while (rayQueryProceedEXT(query)) {
  }
  if (rayQueryGetIntersectionTypeEXT(query, true) != gl_RayQueryCommittedIntersectionNoneEXT) {
    hit = uvec4(uint(rayQueryGetIntersectionInstanceCustomIndexEXT(query, true)),
                uint(rayQueryGetIntersectionPrimitiveIndexEXT(query, true)),
                floatBitsToUint(rayQueryGetIntersectionTEXT(query, true)), 1u);
  }
#endif
  hits.values[i] = hit;
}
