// renderer/scene_bindings.glsl: the scene buffers every tracing pass binds (names are bindings).
// Binding numbers 0..9 are reserved for these; passes number their own from 10.
#ifndef ASVGF_FRAME_SCENE_BINDINGS_GLSL
#define ASVGF_FRAME_SCENE_BINDINGS_GLSL

#include "common/bsdf.glsl"
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
layout(set = 0, binding = 7, std430) readonly buffer TriangleUvs { TriangleUv values[]; } triangle_uvs;
// The texture table (4 uints per texture: offset, width, height, 0), then the texels.
layout(set = 0, binding = 9, std430) readonly buffer Texels { uint values[]; } texels;

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

// Diffuse albedo at a point of a triangle: the material's, times its texture when it has one
// (nearest texel, repeating; untextured materials fetch nothing).
// One return (see common/trace.glsl's intersect_triangle).
vec3 surface_albedo(uint tri, vec2 bary) {
  uint material = triangles.values[tri].material;
  vec4 a = materials.values[material].albedo;
  vec3 albedo = a.rgb;
  if (!(a.w < 0.5)) {
    uint tex = uint(a.w + 0.5) - 1u;
    vec2 uv = triangle_uvs.values[tri].uv0 * (1.0 - bary.x - bary.y) + triangle_uvs.values[tri].uv1 * bary.x +
              triangle_uvs.values[tri].uv2 * bary.y;
    uint offset = texels.values[4u * tex];
    uint w = texels.values[4u * tex + 1u];
    uint h = texels.values[4u * tex + 2u];
    vec2 f = fract(uv);
    uvec2 t = min(uvec2(f * vec2(float(w), float(h))), uvec2(w - 1u, h - 1u));
    vec3 srgb = unpackUnorm4x8(texels.values[offset + t.y * w + t.x]).rgb;
    albedo = a.rgb * srgb_to_linear(srgb);
  }
  return albedo;
}

// Whether the triangle's material has a GGX lobe (common/bsdf.glsl); if not it is Lambertian.
bool triangle_glossy(uint tri) {
  vec4 s = materials.values[triangles.values[tri].material].surface;
  return is_glossy(s.y, s.z);
}
// The glossy model of the triangle's material, with `base` its (textured) surface_albedo.
Glossy triangle_glossy_model(uint tri, vec3 base) {
  vec4 s = materials.values[triangles.values[tri].material].surface;
  return make_glossy(base, s.x, s.y, s.z);
}

// One return in these (see common/trace.glsl's intersect_triangle).
// The albedo the denoiser divides illumination by and composite multiplies back: the surface's
// (a glossy one's directional albedo seen at cos(theta) = n_v), but 1 on emitters, whose emitted
// radiance is not reflectance-modulated; dividing it by a dark albedo would push a valid emission
// (<= 65504) past what the fp16 histories hold.
vec3 demodulation_albedo(uint tri, vec2 bary, float n_v) {
  vec3 albedo = vec3(1.0);
  if (!(materials.values[triangles.values[tri].material].emission.a > 0.0)) {
    albedo = surface_albedo(tri, bary);
    if (triangle_glossy(tri)) {
      float roughness = materials.values[triangles.values[tri].material].surface.x;
      albedo = glossy_albedo(triangle_glossy_model(tri, albedo), roughness, clamp(n_v, 0.0, 1.0));
    }
  }
  return albedo;
}

// The two albedos when the denoiser filters diffuse and specular light apart: the diffuse lobe's
// (a Lambertian surface's albedo) and the GGX lobe's directional albedo (0 where there is no GGX
// lobe: its signal is 0 there, and specular light the filters spread onto it must not show). 1 and
// 0 on emitters, whose emission is the diffuse signal, as above.
void split_demodulation_albedos(uint tri, vec2 bary, float n_v, out vec3 diffuse, out vec3 specular) {
  diffuse = vec3(1.0);
  specular = vec3(0.0);
  if (!(materials.values[triangles.values[tri].material].emission.a > 0.0)) {
    diffuse = surface_albedo(tri, bary);
    if (triangle_glossy(tri)) {
      float roughness = materials.values[triangles.values[tri].material].surface.x;
      Glossy g = triangle_glossy_model(tri, diffuse);
      float c = clamp(n_v, 0.0, 1.0);
      diffuse = diffuse_weight(g, c);
      specular = max(glossy_specular_albedo_fit(g, roughness, c), vec3(0.0));
    }
  }
}

#include "common/trace.glsl"

#endif
