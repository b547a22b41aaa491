// frame/scene_bindings.glsl: the scene buffers every tracing pass binds (names are bindings).
// Binding numbers 0..9 are reserved for these; passes number their own from 10.
#ifndef ASVGF_FRAME_SCENE_BINDINGS_GLSL
#define ASVGF_FRAME_SCENE_BINDINGS_GLSL

#include "common/scene_data.glsl"

// The including shader enables GL_EXT_ray_query (directives must precede declarations).
#ifdef TRACE_RAY_QUERY
layout(set = 0, binding = 1) uniform accelerationStructureEXT scene;
#else
layout(set = 0, binding = 1, std430) readonly buffer BvhNodes { BvhNode values[]; } bvh_nodes;
layout(set = 0, binding = 2, std430) readonly buffer BvhTriangles { uint values[]; } bvh_triangles;
#endif
layout(set = 0, binding = 3, std430) readonly buffer Triangles { Triangle values[]; } triangles;
layout(set = 0, binding = 4, std430) readonly buffer Materials { Material values[]; } materials;
layout(set = 0, binding = 5, std430) readonly buffer Lights { Light values[]; } lights;

// Field-by-field loads: a whole-struct copy out of a buffer becomes OpCopyLogical, which naga
// (the WGSL step) cannot translate.
Triangle load_triangle(uint i) {
  Triangle t;
  t.p0 = triangles.values[i].p0;
  t.material = triangles.values[i].material;
  t.p1 = triangles.values[i].p1;
  t.instance = triangles.values[i].instance;
  t.p2 = triangles.values[i].p2;
  t.primitive = triangles.values[i].primitive;
  return t;
}

Light load_light(uint i) {
  Light l;
  l.position = lights.values[i].position;
  l.radius = lights.values[i].radius;
  l.emission = lights.values[i].emission;
  l.type = lights.values[i].type;
  l.prev_position = lights.values[i].prev_position;
  l.pdf = lights.values[i].pdf;
  l.triangle = lights.values[i].triangle;
  l.area = lights.values[i].area;
  l.pad0 = 0u;
  l.pad1 = 0u;
  return l;
}

#include "common/trace.glsl"

#endif
