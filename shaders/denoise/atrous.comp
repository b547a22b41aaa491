// atrous.comp: one iteration of SVGF's edge-avoiding a-trous wavelet filter (Schied et al. 2017,
// eq. 1-4; the seed's w_z, w_n, w_l). Taps at p + step * (i, j): a 5x5 B3-spline kernel (paper) or a
// 3x3 box (seed), chosen by `kernel`. Colour is averaged with h * w; the variance in alpha with
// (h * w)^2 / (sum h * w)^2. The luminance weight uses the 3x3-binomial-prefiltered variance.
// The HISTORY variant also writes its output to the colour history (the configurable history tap).
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#include "common/compute.glsl"
#include "common/denoise.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform Params {
  uint width;
  uint height;
  int step;    // 2^iteration
  uint kernel;  // 0: 5x5 B3 spline, 1: 3x3 box
  float sigma_z;
  float sigma_n;
  float sigma_l;
} params;
layout(set = 0, binding = 1) uniform texture2D color_in;  // rgb colour, a variance
layout(set = 0, binding = 2) uniform texture2D depth_normal;
layout(set = 0, binding = 3, rgba16f) writeonly uniform image2D color_out;
#ifdef HISTORY
layout(set = 0, binding = 4, rgba16f) writeonly uniform image2D color_history;
#endif

ivec2 clamp_pixel(ivec2 q) { return clamp(q, ivec2(0), ivec2(params.width, params.height) - 1); }

float prefiltered_variance(ivec2 p) {
  float v = 0.0;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx)
      v += binomial3(dx) * binomial3(dy) * texelFetch(color_in, clamp_pixel(p + ivec2(dx, dy)), 0).a;
  return v;
}

void main() {
  ivec2 p = invocation_pixel();
  if (!inside(p, params.width, params.height)) return;
  vec4 c = texelFetch(color_in, p, 0);
  Surface center = surface_from(texelFetch(depth_normal, p, 0));
  vec4 result = c;
  if (hit(center)) {
    float lp = luminance(c.rgb);
    float std_dev = sqrt(max(prefiltered_variance(p), 0.0));
    int radius = params.kernel == 0u ? 2 : 1;
    vec3 sum_c = vec3(0.0);
    float sum_v = 0.0, sum_w = 0.0;
    for (int dy = -radius; dy <= radius; ++dy) {
      for (int dx = -radius; dx <= radius; ++dx) {
        ivec2 q = p + params.step * ivec2(dx, dy);
        if (q.x < 0 || q.y < 0 || !inside(q, params.width, params.height)) continue;
        float h = params.kernel == 0u ? b3spline(dx) * b3spline(dy) : 1.0;
        vec4 cq = texelFetch(color_in, q, 0);
        float w = h;
        if (dx != 0 || dy != 0) {
          Surface other = surface_from(texelFetch(depth_normal, q, 0));
          float dist = float(params.step * (abs(dx) + abs(dy)));
          w *= weight_depth(center, other, dist, params.sigma_z) * weight_normal(center, other, params.sigma_n) *
               weight_luminance(lp, luminance(cq.rgb), params.sigma_l, std_dev);
        }
        sum_c += w * cq.rgb;
        sum_v += w * w * cq.a;
        sum_w += w;
      }
    }
    result = vec4(sum_c / sum_w, sum_v / (sum_w * sum_w));
  }
  result = clamp_fp16(result);
  imageStore(color_out, p, result);
#ifdef HISTORY
  imageStore(color_history, p, result);
#endif
}
