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

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform Params {
  uint width;  // full resolution
  uint height;
  uint gradient_width;  // ceil(width / 3)
  uint gradient_height;
  uint history_valid;  // 0: no last frame (first frame, reset): no gradient
} params;
layout(set = 0, binding = 1) uniform texture2D illumination;
layout(set = 0, binding = 2) uniform texture2D motion;
layout(set = 0, binding = 3) uniform texture2D depth_normal;
layout(set = 0, binding = 4) uniform texture2D prev_depth_normal;
layout(set = 0, binding = 5) uniform texture2D prev_noisy_luminance;
layout(set = 0, binding = 6, r32f) writeonly uniform image2D noisy_luminance;
layout(set = 0, binding = 7, rgba16f) writeonly uniform image2D gradient;

void main() {
  ivec2 s = invocation_pixel();
  if (!inside(s, params.gradient_width, params.gradient_height)) return;
  float sum_cur = 0.0, sum_prev = 0.0;
  for (int i = 0; i < 9; ++i) {
    ivec2 p = 3 * s + ivec2(i % 3, i / 3);
    if (!inside(p, params.width, params.height)) continue;
    vec3 c = texelFetch(illumination, p, 0).rgb;
    bool finite = !any_not_finite(c);
    float l = finite ? luminance(clamp_sample(c)) : 0.0;
    imageStore(noisy_luminance, p, vec4(l, 0.0, 0.0, 0.0));
    Surface cur = surface_from(texelFetch(depth_normal, p, 0));
    if (params.history_valid == 0u || !finite || !hit(cur)) continue;
    vec2 q = vec2(p) + 0.5 + texelFetch(motion, p, 0).xy;
    if (!(q.x >= 0.0 && q.y >= 0.0 && q.x < float(params.width) && q.y < float(params.height))) continue;
    ivec2 qi = ivec2(q);
    if (!reprojection_consistent(cur, surface_from(texelFetch(prev_depth_normal, qi, 0)))) continue;
    float lp = texelFetch(prev_noisy_luminance, qi, 0).x;
    if (not_finite(lp)) continue;
    sum_cur += l;
    sum_prev += clamp(lp, 0.0, kFp16Max);
  }
  vec2 result = vec2(sum_cur - sum_prev, max(sum_cur, sum_prev));
  imageStore(gradient, s, vec4(clamp(result, vec2(-kFp16Max), vec2(kFp16Max)), 0.0, 0.0));
}
