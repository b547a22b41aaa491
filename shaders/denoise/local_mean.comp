// local_mean.comp: the local-mean correction (DenoiseSettings::local_mean, opt-in): scales the
// filtered colour toward the temporal result's k x k local mean of luminance. The a-trous
// gather, normalised per pixel, loses energy where a bright pixel's neighbours are darker and takes
// local contrast everywhere; the temporal result holds neither loss, and its k x k mean is far less
// noisy than its pixels (docs/quality.md, "Energy: a correction of the displayed frame's local
// mean"). The scale is shrunk toward 1 where the box mean of the temporal result is not known
// better than its difference from the filtered one's: 1 + g (ratio - 1), g = d^2 / (d^2 + se^2), d
// the difference of the means, se^2 the box's spatial variance of the temporal luminance over k^2
// (its standard error if the pixels' noise were independent); measured offline, the gate had 7-20%
// less error than the plain ratio at 64-256 px, keeping the energy bias within about 1%. Two
// passes, a box separated: ROWS writes each pixel's row means of both luminances and of the
// temporal one squared (window clamped at the image's edges), the other averages them down the
// column and scales.
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
  uint gated;  // 0: the plain ratio (the tapped history's correction, whose bias would accumulate)
} params;
#ifdef ROWS
layout(set = 0, binding = 1) uniform texture2D temporal;  // the temporal pass's result
layout(set = 0, binding = 2) uniform texture2D filtered;  // the last a-trous iteration's
// x: temporal, y: filtered, z: temporal squared
layout(set = 0, binding = 3, rgba32f) writeonly uniform image2D row_means;
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
  vec3 sum = vec3(0.0);
  for (int x = lo; x <= hi; ++x) {
    ivec2 q = ivec2(x, p.y);
    float t = luminance(texelFetch(temporal, q, 0).rgb);
    sum += vec3(t, luminance(texelFetch(filtered, q, 0).rgb), t * t);
  }
  imageStore(row_means, p, vec4(sum / float(hi - lo + 1), 0.0));
#else
  int lo = max(p.y - params.radius, 0);
  int hi = min(p.y + params.radius, int(params.height) - 1);
  vec3 sum = vec3(0.0);
  for (int y = lo; y <= hi; ++y) sum += texelFetch(row_means, ivec2(p.x, y), 0).xyz;
  vec3 mean = sum / float(hi - lo + 1);
  float k = float(2 * params.radius + 1);
  float d2 = (mean.x - mean.y) * (mean.x - mean.y);
  float se2 = max(mean.z - mean.x * mean.x, 0.0) / (k * k);
  float g = params.gated == 0u ? 1.0 : d2 + se2 > 0.0 ? d2 / (d2 + se2) : 0.0;
  // Nothing filtered to scale (a black neighbourhood): left as it is.
  float scale = mean.y > 1e-6 ? 1.0 + g * (mean.x / mean.y - 1.0) : 1.0;
  vec4 f = texelFetch(filtered, p, 0);
  imageStore(corrected, p, round_to_half(clamp_fp16(vec4(f.rgb * scale, f.a))));
#endif
}
