// gradient_reprojected.comp: A-SVGF's temporal gradient without the renderer's help (no re-shaded
// samples), at 1/3 resolution, in the manner of Q2RTX's low-frequency gradient: per 3x3 stratum,
// this frame's noisy luminance and last frame's noisy luminance reprojected through the motion
// vectors, summed over the pixels whose reprojection is consistent (depth and normal, as the
// temporal pass tests them; nearest pixel): delta = sum_cur - sum_prev, Delta = max(sum_cur,
// sum_prev), the same (delta, Delta) the re-shaded `gradient` pass writes, for gradient_atrous and
// the adaptive temporal pass. Unlike re-shading, the two sums carry independent noise: a static
// scene still shows a gradient of the order of the noise (the a-trous sums over strata shrink it).
// It also writes this frame's luminance (the next frame's history) for every pixel of the stratum.
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#include "common/compute.glsl"
#include "common/denoise.glsl"

// One invocation per pixel, a 12x9 workgroup covering 4x3 strata (108 invocations: Vulkan and GLES
// guarantee 128): each invocation reprojects its
// pixel, then one invocation per stratum sums the 9 results from shared memory in pixel order (a
// loop over the 9 pixels in one invocation per stratum ran at 3x the pass's bandwidth floor: too
// little parallelism).
layout(local_size_x = 12, local_size_y = 9) in;
shared vec2 pixel_sums[108];  // (l_cur, l_prev) of a consistent pixel, (-1, 0) otherwise

layout(set = 0, binding = 0) uniform Params {
  uint width;  // full resolution
  uint height;
  uint gradient_width;  // ceil(width / 3)
  uint gradient_height;
  uint history_valid;  // 0: no last frame (first frame, reset): no gradient
} params;
layout(set = 0, binding = 1) uniform texture2D illumination;
#define MOTION_BINDING 2  // float, or halves with MOTION_HALVES
#include "common/motion.glsl"
layout(set = 0, binding = 3) uniform utexture2D depth_normal;
layout(set = 0, binding = 4) uniform utexture2D prev_depth_normal;
layout(set = 0, binding = 5) uniform texture2D prev_noisy_luminance;
layout(set = 0, binding = 6, r32f) writeonly uniform image2D noisy_luminance;
layout(set = 0, binding = 7, rgba16f) writeonly uniform image2D gradient;

// (l_cur, l_prev) of pixel p when its reprojection is consistent, else (-1, 0); writes its luminance.
vec2 reproject(ivec2 p) {
  vec3 c = texelFetch(illumination, p, 0).rgb;
  bool finite = !any_not_finite(c);
  float l = finite ? luminance(clamp_sample(c)) : 0.0;
  imageStore(noisy_luminance, p, vec4(l, 0.0, 0.0, 0.0));
  Surface cur = surface_from(texelFetch(depth_normal, p, 0));
  if (params.history_valid == 0u || !finite || !hit(cur)) return vec2(-1.0, 0.0);
  vec2 q = vec2(p) + 0.5 + motion_at(p).xy;
  if (!(q.x >= 0.0 && q.y >= 0.0 && q.x < float(params.width) && q.y < float(params.height))) return vec2(-1.0, 0.0);
  ivec2 qi = ivec2(q);
  if (!reprojection_consistent(cur, surface_from(texelFetch(prev_depth_normal, qi, 0)))) return vec2(-1.0, 0.0);
  float lp = texelFetch(prev_noisy_luminance, qi, 0).x;
  if (not_finite(lp)) return vec2(-1.0, 0.0);
  return vec2(l, clamp(lp, 0.0, kFp16Max));
}

// The stratum's sum over its 3x3 pixels (their values in pixel_sums).
void write_stratum(ivec2 local, ivec2 s) {
  float sum_cur = 0.0, sum_prev = 0.0;
  for (int i = 0; i < 9; ++i) {
    vec2 v = pixel_sums[(3 * local.y + i / 3) * 12 + 3 * local.x + i % 3];
    if (v.x < 0.0) continue;
    sum_cur += v.x;
    sum_prev += v.y;
  }
  vec2 result = vec2(sum_cur - sum_prev, max(sum_cur, sum_prev));
  imageStore(gradient, s, vec4(round_to_half(clamp(result, vec2(-kFp16Max), vec2(kFp16Max))), 0.0, 0.0));
}

// No return in main: one puts the barrier inside the loop construct that inlining makes of it.
void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 local = ivec2(gl_LocalInvocationID.xy);
  pixel_sums[local.y * 12 + local.x] = inside(p, params.width, params.height) ? reproject(p) : vec2(-1.0, 0.0);
  barrier();
  ivec2 s = ivec2(gl_WorkGroupID.xy) * ivec2(4, 3) + local;
  if (local.x < 4 && local.y < 3 && inside(s, params.gradient_width, params.gradient_height)) write_stratum(local, s);
}
