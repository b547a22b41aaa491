// hal_test_ray_query.comp: one ray per invocation against `scene`, committed hit written out.
// Used by the Vulkan backend's tests. The `rayquery` variant defines TRACE_RAY_QUERY; without it
// the shader only clears the hits (there is no software path to test here). The `rayquery_boxes`
// variant also defines BOXES: `scene` holds boxes, and the shader commits the nearest box entry
// point of the candidates the traversal reports.
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
#ifdef BOXES
// Six floats per box: min.xyz, max.xyz (the BLAS's own box buffer).
layout(set = 0, binding = 4) readonly buffer Boxes { float values[]; } boxes;

// Where the ray enters box `b` within [tmin, tmax], or -1 when it misses it.
float box_entry(uint b, vec3 o, vec3 d, float tmin, float tmax) {
  vec3 lo = vec3(boxes.values[6u * b], boxes.values[6u * b + 1u], boxes.values[6u * b + 2u]);
  vec3 hi = vec3(boxes.values[6u * b + 3u], boxes.values[6u * b + 4u], boxes.values[6u * b + 5u]);
  vec3 t0 = (lo - o) / d;
  vec3 t1 = (hi - o) / d;
  float enter = max(max(min(t0.x, t1.x), min(t0.y, t1.y)), max(min(t0.z, t1.z), tmin));
  float leave = min(min(max(t0.x, t1.x), max(t0.y, t1.y)), min(max(t0.z, t1.z), tmax));
  return enter <= leave ? enter : -1.0;
}
#endif
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
#ifdef BOXES
    if (rayQueryGetIntersectionTypeEXT(query, false) == gl_RayQueryCandidateIntersectionAABBEXT) {
      uint b = uint(rayQueryGetIntersectionPrimitiveIndexEXT(query, false));
      float committed = rayQueryGetIntersectionTypeEXT(query, true) == gl_RayQueryCommittedIntersectionNoneEXT
                            ? direction.w
                            : rayQueryGetIntersectionTEXT(query, true);
      float t = box_entry(b, origin.xyz, direction.xyz, origin.w, committed);
      if (t >= 0.0 && t < committed) rayQueryGenerateIntersectionEXT(query, t);
    }
#endif
  }
  if (rayQueryGetIntersectionTypeEXT(query, true) != gl_RayQueryCommittedIntersectionNoneEXT) {
    hit = uvec4(uint(rayQueryGetIntersectionInstanceCustomIndexEXT(query, true)),
                uint(rayQueryGetIntersectionPrimitiveIndexEXT(query, true)),
                floatBitsToUint(rayQueryGetIntersectionTEXT(query, true)), 1u);
  }
#endif
  hits.values[i] = hit;
}
