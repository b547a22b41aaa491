// validate_inputs.comp: counts what is wrong with a frame's denoiser inputs (the public API's
// conventions, include/asvgf/denoiser.hpp), for asvgf::Denoiser's `validate` option: non-finite and
// negative values, normals that are not unit length, and whether the motion vectors lead to the same
// surface in the previous frame as given or negated (the usual sign mistake). The counts go to an
// SSBO (atomics: image atomics are not portable); pipeline/denoiser/api/input_report.cpp words them.
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#include "common/compute.glsl"
#include "common/surface.glsl"
#include "common/denoise.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform Params {
  uint width;
  uint height;
  uint history_valid;  // 0: no previous frame to test the motion against
  uint pad;
} params;
layout(set = 0, binding = 1) uniform texture2D illumination;
layout(set = 0, binding = 2) uniform texture2D albedo;
layout(set = 0, binding = 3) uniform texture2D normal;
layout(set = 0, binding = 4) uniform texture2D depth;
layout(set = 0, binding = 5) uniform texture2D motion;
layout(set = 0, binding = 6) uniform utexture2D prev_depth_normal;
// Indices as kInputCounts in pipeline/denoiser/api/input_report.hpp.
layout(set = 0, binding = 7) buffer Counts { uint values[16]; } counts;

const float kSameSurface = 0.05;  // relative depth difference of "the same surface"

void count(uint index, bool condition) {
  if (condition) atomicAdd(counts.values[index], 1u);
}

// 1 when the previous frame's depth where `p` lands after moving by `d` matches z.
bool lands_on_same_surface(ivec2 p, vec2 d, float z) {
  vec2 q = vec2(p) + 0.5 + d;
  if (!(q.x >= 0.0 && q.y >= 0.0 && q.x < float(params.width) && q.y < float(params.height))) return false;
  float zp = depth_normal_depth(texelFetch(prev_depth_normal, ivec2(q), 0));
  return zp > 0.0 && abs(zp - z) <= kSameSurface * z;
}

void main() {
  ivec2 p = invocation_pixel();
  if (!inside(p, params.width, params.height)) return;
  vec3 c = texelFetch(illumination, p, 0).rgb;
  vec3 a = texelFetch(albedo, p, 0).rgb;
  vec3 n = texelFetch(normal, p, 0).xyz;
  float z = texelFetch(depth, p, 0).x;
  vec2 mv = texelFetch(motion, p, 0).xy;
  count(0u, true);
  count(1u, any_not_finite(c));
  count(2u, !any_not_finite(c) && any(lessThan(c, vec3(0.0))));
  count(3u, any_not_finite(a) || any(lessThan(a, vec3(0.0))));
  count(7u, not_finite(z));
  count(8u, !not_finite(z) && z < 0.0);
  // Surface as the denoiser sees it (common/surface.glsl), but a normal that is not finite on a
  // surface depth is counted as a bad normal rather than called background.
  bool surface = !background_depth(z) && !(background_normal(n) && !any_not_finite(n));
  count(4u, surface);
  if (surface) {
    count(6u, any_not_finite(n));
    float len = length(n);
    count(5u, !any_not_finite(n) && abs(len - 1.0) > 0.1);
  }
  count(9u, not_finite(mv.x) || not_finite(mv.y));
  bool moving = surface && !not_finite(mv.x) && !not_finite(mv.y) && length(mv) >= 0.5 && length(mv) < 1e5;
  if (moving && params.history_valid != 0u) {
    count(10u, true);
    count(11u, lands_on_same_surface(p, mv, z));
    count(12u, lands_on_same_surface(p, -mv, z));
  }
  count(13u, !any_not_finite(c) && any(greaterThan(c, vec3(kFp16Max))));
}
