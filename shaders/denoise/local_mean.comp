// local_mean.comp: the local-mean correction (DenoiseSettings::local_mean, opt-in): scales the
// filtered colour so that its k x k local mean of luminance is the temporal result's. The a-trous
// gather, normalised per pixel, loses energy where a bright pixel's neighbours are darker and takes
// local contrast everywhere; the temporal result holds neither loss, and its k x k mean is far less
// noisy than its pixels (docs/quality.md, "Energy: a correction of the displayed frame's local
// mean"). Two passes, a box separated: ROWS writes each pixel's row means of both luminances
// (window clamped at the image's edges), the other averages them down the column and scales.
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#include "common/color.glsl"
#include "common/compute.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform Params {
  uint width;
  uint height;
  int radius;  // (k - 1) / 2
} params;
#ifdef ROWS
layout(set = 0, binding = 1) uniform texture2D temporal;  // the temporal pass's result
layout(set = 0, binding = 2) uniform texture2D filtered;  // the last a-trous iteration's
layout(set = 0, binding = 3, rgba32f) writeonly uniform image2D row_means;  // x: temporal, y: filtered (ES has no rg32f images)
#else
layout(set = 0, binding = 1) uniform texture2D row_means;
layout(set = 0, binding = 2) uniform texture2D filtered;
layout(set = 0, binding = 3, rgba16f) writeonly uniform image2D corrected;
#endif

void main() {
  ivec2 p = invocation_pixel();
  if (!inside(p, params.width, params.height)) return;
#ifdef ROWS
  int lo = max(p.x - params.radius, 0);
  int hi = min(p.x + params.radius, int(params.width) - 1);
  vec2 sum = vec2(0.0);
  for (int x = lo; x <= hi; ++x) {
    ivec2 q = ivec2(x, p.y);
    sum += vec2(luminance(texelFetch(temporal, q, 0).rgb), luminance(texelFetch(filtered, q, 0).rgb));
  }
  imageStore(row_means, p, vec4(sum / float(hi - lo + 1), 0.0, 0.0));
#else
  int lo = max(p.y - params.radius, 0);
  int hi = min(p.y + params.radius, int(params.height) - 1);
  vec2 sum = vec2(0.0);
  for (int y = lo; y <= hi; ++y) sum += texelFetch(row_means, ivec2(p.x, y), 0).xy;
  vec2 mean = sum / float(hi - lo + 1);
  // Nothing filtered to scale (a black neighbourhood): left as it is.
  float scale = mean.y > 1e-6 ? mean.x / mean.y : 1.0;
  vec4 f = texelFetch(filtered, p, 0);
  imageStore(corrected, p, round_to_half(clamp_fp16(vec4(f.rgb * scale, f.a))));
#endif
}
