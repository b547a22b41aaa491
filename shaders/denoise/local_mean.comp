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
// column and scales. The row pass reads its workgroup's row and its apron once into shared memory and
// sums each window there (reading every tap from the images cost 0.65 ms a frame at k 33 and
// 1080p: docs/quality.md); the column pass slides a running sum down a strip of kStrip rows an
// invocation, two row reads an output whatever k is, and starts each strip's sum afresh so that the
// sum's rounding does not build up (docs/quality.md, "The column pass as a running sum").
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#include "common/color.glsl"
#include "common/compute.glsl"

#ifdef ROWS
// The largest radius (k 255) sizes the tile: 382 entries, under the 16 KB of shared memory WebGPU
// and OpenGL ES guarantee (three floats an entry).
const int kMaxRadius = 127;
const int kGroupX = 128;
layout(local_size_x = kGroupX, local_size_y = 1) in;
const int kTileEntries = kGroupX + 2 * kMaxRadius;  // one row and its apron
#else
const int kStrip = 16;  // rows an invocation writes (the pass dispatches ceil(height / kStrip) rows of invocations)
layout(local_size_x = 64, local_size_y = 1) in;
#endif

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

#ifdef ROWS
// The three sums' terms of the tile's pixels (0 outside the image, where no window reaches).
shared float tile_t[kTileEntries];
shared float tile_f[kTileEntries];
shared float tile_t2[kTileEntries];

// One row: entry i is pixel (x0 - radius + i, y).
void load_tile(ivec2 origin) {
  const int length = kGroupX + 2 * params.radius;
  for (int i = int(gl_LocalInvocationIndex); i < length; i += kGroupX) {
    const ivec2 q = ivec2(origin.x - params.radius + i, origin.y);
    vec3 terms = vec3(0.0);
    if (q.x >= 0 && inside(q, params.width, params.height)) {
      const float t = luminance(texelFetch(temporal, q, 0).rgb);
      terms = vec3(t, luminance(texelFetch(filtered, q, 0).rgb), t * t);
    }
    tile_t[i] = terms.x;
    tile_f[i] = terms.y;
    tile_t2[i] = terms.z;
  }
}

// The window's mean of the three terms, its pixels clamped to the image.
vec3 window_mean(ivec2 p, ivec2 origin) {
  const int lo = max(p.x - params.radius, 0), hi = min(p.x + params.radius, int(params.width) - 1);
  const int first = lo - (origin.x - params.radius);
  vec3 sum = vec3(0.0);
  for (int i = first; i <= first + hi - lo; ++i) sum += vec3(tile_t[i], tile_f[i], tile_t2[i]);
  return sum / float(hi - lo + 1);
}

// No return in main: one puts the barrier inside the loop construct that inlining makes of it
// (suspected of stalling NVIDIA's OpenGL SPIR-V path: docs/performance.md).
void main() {
  const ivec2 origin = ivec2(gl_WorkGroupID.xy) * ivec2(kGroupX, 1);
  load_tile(origin);
  barrier();
  ivec2 p = invocation_pixel();
  if (inside(p, params.width, params.height)) imageStore(row_means, p, vec4(window_mean(p, origin), 0.0));
}
#else
vec3 row_mean(int x, int y) { return texelFetch(row_means, ivec2(x, y), 0).xyz; }

// The correction at p from its window's means (x: temporal, y: filtered, z: temporal squared).
void correct(ivec2 p, vec3 mean) {
  float k = float(2 * params.radius + 1);
  float d2 = (mean.x - mean.y) * (mean.x - mean.y);
  float se2 = max(mean.z - mean.x * mean.x, 0.0) / (k * k);
  float g = params.gated == 0u ? 1.0 : d2 + se2 > 0.0 ? d2 / (d2 + se2) : 0.0;
  // Nothing filtered to scale (a black neighbourhood): left as it is.
  float scale = mean.y > 1e-6 ? 1.0 + g * (mean.x / mean.y - 1.0) : 1.0;
  vec4 f = texelFetch(filtered, p, 0);
  imageStore(corrected, p, round_to_half(clamp_fp16(vec4(f.rgb * scale, f.a))));
}

// Column x, rows [y0, y0 + kStrip): the first window summed, then each next one by the row that
// enters it and the row that leaves it (windows clamped to the image).
void main() {
  const int x = int(gl_GlobalInvocationID.x);
  const int y0 = int(gl_GlobalInvocationID.y) * kStrip;
  const int last = int(params.height) - 1;
  if (x < int(params.width) && y0 <= last) {
    vec3 sum = vec3(0.0);
    for (int y = max(y0 - params.radius, 0); y <= min(y0 + params.radius, last); ++y) sum += row_mean(x, y);
    for (int y = y0; y < min(y0 + kStrip, last + 1); ++y) {
      if (y > y0) {
        if (y + params.radius <= last) sum += row_mean(x, y + params.radius);
        if (y - params.radius - 1 >= 0) sum -= row_mean(x, y - params.radius - 1);
      }
      const int count = min(y + params.radius, last) - max(y - params.radius, 0) + 1;
      correct(ivec2(x, y), sum / float(count));
    }
  }
}
#endif
