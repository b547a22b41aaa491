// common/scene_data.glsl: the scene's GPU layouts (mirrors pipeline/renderer/scene_gpu.hpp) and the
// camera. Buffers themselves are declared by each shader, since their names are its bindings.
#ifndef ASVGF_COMMON_SCENE_DATA_GLSL
#define ASVGF_COMMON_SCENE_DATA_GLSL

struct Triangle {
  vec3 p0;
  uint material;
  vec3 p1;
  uint instance;
  vec3 p2;
  uint primitive;
};

struct Material {
  vec4 albedo;
  vec4 emission;  // a = 1 when emissive
  vec4 surface;   // roughness, metallic, specular (common/bsdf.glsl), 0
};

struct Light {
  vec3 position;
  float radius;
  vec3 emission;
  uint type;  // 0 sphere, 1 emissive triangle
  vec3 prev_position;
  float pdf;
  uint triangle;
  float area;
  uint pad0;
  uint pad1;
};

struct TriangleUv {
  vec2 uv0;
  vec2 uv1;
  vec2 uv2;
  vec2 pad;
};

// The sRGB transfer function, inverted (IEC 61966-2-1).
vec3 srgb_to_linear(vec3 c) {
  return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), step(vec3(0.04045), c));
}

struct BvhNode {
  vec3 bmin;
  uint first;
  vec3 bmax;
  uint count;
};

struct Camera {
  vec4 position;
  vec4 forward;
  vec4 right;  // scaled by tan(fov/2) * aspect
  vec4 up;     // scaled by tan(fov/2)
};

// Copies a Camera out of a uniform block member by member (a whole-struct copy becomes
// OpCopyLogical, which naga cannot translate).
#define LOAD_CAMERA(dst, src)      \
  dst.position = src.position;     \
  dst.forward = src.forward;       \
  dst.right = src.right;           \
  dst.up = src.up

vec3 camera_ray(Camera c, vec2 pixel, uint width, uint height) {
  vec2 ndc = vec2(2.0 * pixel.x / float(width) - 1.0, 1.0 - 2.0 * pixel.y / float(height));
  return normalize(c.forward.xyz + ndc.x * c.right.xyz + ndc.y * c.up.xyz);
}

// Pixel coordinates (not centres) where a world point appears; z = view depth (<= 0: behind).
vec3 camera_project(Camera c, vec3 p, uint width, uint height) {
  vec3 v = p - c.position.xyz;
  float z = dot(v, c.forward.xyz);
  vec2 ndc = vec2(dot(v, c.right.xyz) / dot(c.right.xyz, c.right.xyz),
                  dot(v, c.up.xyz) / dot(c.up.xyz, c.up.xyz)) / max(z, 1e-20);
  return vec3((ndc.x + 1.0) * 0.5 * float(width), (1.0 - ndc.y) * 0.5 * float(height), z);
}

#include "common/color.glsl"  // luminance(), for the glossy lobe's choice and the split signals

#endif
