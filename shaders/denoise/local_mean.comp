// local_mean.comp: the local-mean correction (DenoiseSettings::local_mean, opt-in): scales the
// filtered colour toward the temporal result's local mean of luminance over a window about k pixels
// wide. The a-trous gather, normalised per pixel, loses energy where a bright pixel's neighbours are
// darker and takes local contrast everywhere; the temporal result holds neither loss, and its local
// mean is far less noisy than its pixels (docs/quality.md, "Energy: a correction of the displayed
// frame's local mean"). The scale is shrunk toward 1 where the box mean of the temporal result is
// not known better than its difference from the filtered one's: 1 + g (ratio - 1), g = d^2 / (d^2 +
// se^2), d the difference of the means, se^2 the box's spatial variance of the temporal luminance
// over the window's pixel count (its standard error if the pixels' noise were independent).
// The window is a box of (2 radius + 1)^2 blocks of block x block pixels (local_mean_blocks in
// denoiser/passes/local_mean.hpp: blocks of 1 pixel up to k 15, so that small windows are exact, and
// about 9 blocks a side above), read between the four nearest blocks' boxes bilinearly. Three passes:
// BLOCKS sums each block's three terms (both luminances and the temporal one squared) and pixel
// count, BOX sums them over each block's window of blocks (clamped to the image), the last
// interpolates and scales. Two k-wide separable passes over every pixel cost 0.26 ms at 1080p and k
// 65; the block passes touch each pixel once (docs/quality.md, "The box over blocks").
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#include "common/color.glsl"
#include "common/compute.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform Params {
  uint width;
  uint height;
  int radius;   // in blocks
  uint gated;   // 0: the plain ratio (the tapped history's correction, whose bias would accumulate)
  int block;    // pixels a block's side: 1, 2, 4 or 8
} params;

// The blocks' grid (partial blocks at the right and bottom edges).
ivec2 blocks() { return (ivec2(params.width, params.height) + params.block - 1) / params.block; }
#ifdef BLOCKS
layout(set = 0, binding = 1) uniform texture2D temporal;  // the temporal pass's result
layout(set = 0, binding = 2) uniform texture2D filtered;  // the last a-trous iteration's
// x: temporal, y: filtered, z: temporal squared (sums), w: pixels
layout(set = 0, binding = 3, rgba32f) writeonly uniform image2D block_sums;
#elif defined(BOX)
layout(set = 0, binding = 3) uniform texture2D block_sums;
// x, y, z: the window's means of the three terms
layout(set = 0, binding = 4, rgba32f) writeonly uniform image2D box_means;
#else
layout(set = 0, binding = 2) uniform texture2D filtered;
layout(set = 0, binding = 4) uniform texture2D box_means;
layout(set = 0, binding = 5, rgba16f) writeonly uniform image2D corrected;
#endif

#ifdef BLOCKS
// The workgroup's 8x8 pixels' terms; each block row is summed by its first invocation, then the
// rows by the block's first: 2 block adds in series instead of block^2 (one invocation summing all
// 64 of a block of 8 took 0.055 ms at 1080p).
shared vec4 terms[64];
shared vec4 row_sums[64];

// No return in main: one puts the barrier inside the loop construct that inlining makes of it
// (suspected of stalling NVIDIA's OpenGL SPIR-V path: docs/performance.md).
void main() {
  const ivec2 p = invocation_pixel();
  vec4 t = vec4(0.0);
  if (inside(p, params.width, params.height)) {
    const float lt = luminance(texelFetch(temporal, p, 0).rgb);
    t = vec4(lt, luminance(texelFetch(filtered, p, 0).rgb), lt * lt, 1.0);
  }
  const ivec2 l = ivec2(gl_LocalInvocationID.xy);
  terms[l.y * 8 + l.x] = t;
  barrier();
  const int b = params.block;
  if (l.x % b == 0) {
    vec4 sum = vec4(0.0);
    for (int x = 0; x < b; ++x) sum += terms[l.y * 8 + l.x + x];
    row_sums[l.y * 8 + l.x] = sum;
  }
  barrier();
  const ivec2 q = p / b;  // this pixel's block
  if (l.x % b == 0 && l.y % b == 0 && all(lessThan(q, blocks()))) {
    vec4 sum = vec4(0.0);
    for (int y = 0; y < b; ++y) sum += row_sums[(l.y + y) * 8 + l.x];
    imageStore(block_sums, q, sum);
  }
}
#elif defined(BOX)
void main() {
  const ivec2 q = invocation_pixel();
  if (all(lessThan(q, blocks()))) {
    const ivec2 lo = max(q - params.radius, ivec2(0));
    const ivec2 hi = min(q + params.radius, blocks() - 1);
    vec4 sum = vec4(0.0);
    for (int y = lo.y; y <= hi.y; ++y)
      for (int x = lo.x; x <= hi.x; ++x) sum += texelFetch(block_sums, ivec2(x, y), 0);
    imageStore(box_means, q, vec4(sum.xyz / sum.w, 0.0));
  }
}
#else
vec3 box_mean(int x, int y) { return texelFetch(box_means, ivec2(x, y), 0).xyz; }

// The window's means at p: the four nearest blocks' boxes, bilinearly (block centres at
// (i + 0.5) block), clamped to the blocks' grid. With blocks of 1 pixel, p's own box exactly.
vec3 window_mean(ivec2 p) {
  const vec2 last = vec2(blocks() - 1);
  const vec2 u = clamp((vec2(p) + 0.5) / float(params.block) - 0.5, vec2(0.0), last);
  const ivec2 i0 = ivec2(floor(u));
  const ivec2 i1 = min(i0 + 1, ivec2(last));
  const vec2 f = u - vec2(i0);
  const vec3 top = mix(box_mean(i0.x, i0.y), box_mean(i1.x, i0.y), f.x);
  const vec3 bottom = mix(box_mean(i0.x, i1.y), box_mean(i1.x, i1.y), f.x);
  return mix(top, bottom, f.y);
}

void main() {
  const ivec2 p = invocation_pixel();
  if (inside(p, params.width, params.height)) {
    const vec3 mean = window_mean(p);
    float d2 = (mean.x - mean.y) * (mean.x - mean.y);
    const float window = float((2 * params.radius + 1) * params.block);  // the window's side in pixels
    float se2 = max(mean.z - mean.x * mean.x, 0.0) / (window * window);
    float g = params.gated == 0u ? 1.0 : d2 + se2 > 0.0 ? d2 / (d2 + se2) : 0.0;
    // Nothing filtered to scale (a black neighbourhood): left as it is.
    float scale = mean.y > 1e-6 ? 1.0 + g * (mean.x / mean.y - 1.0) : 1.0;
    vec4 f = texelFetch(filtered, p, 0);
    imageStore(corrected, p, round_to_half(clamp_fp16(vec4(f.rgb * scale, f.a))));
  }
}
#endif
