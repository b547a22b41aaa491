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
// column and scales. Each pass reads its workgroup's span of the image and its apron once into
// shared memory and sums the window there: reading every tap from the images cost 0.65 ms a frame
// at k 33 and 1080p (docs/quality.md).
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#include "common/color.glsl"
#include "common/compute.glsl"

// The largest radius (k 255) sizes the tiles: 382 and 4 x 286 entries, under the 16 KB of shared
// memory WebGPU and OpenGL ES guarantee (three floats an entry).
const int kMaxRadius = 127;
#ifdef ROWS
const int kGroupX = 128;
const int kGroupY = 1;
#else
const int kGroupX = 4;
const int kGroupY = 32;
#endif
layout(local_size_x = kGroupX, local_size_y = kGroupY) in;
#ifdef ROWS
const int kTileEntries = kGroupX + 2 * kMaxRadius;  // one row and its apron
#else
const int kTileEntries = kGroupX * (kGroupY + 2 * kMaxRadius);  // kGroupX columns and their apron
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

// The three sums' terms of the tile's pixels (0 outside the image, where no window reaches).
shared float tile_t[kTileEntries];
shared float tile_f[kTileEntries];
shared float tile_t2[kTileEntries];

#ifdef ROWS
// One row: entry i is pixel (x0 - radius + i, y).
void load_tile(ivec2 origin) {
  const int length = kGroupX + 2 * params.radius;
  for (int i = int(gl_LocalInvocationIndex); i < length; i += kGroupX * kGroupY) {
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
#else
// kGroupX columns: entry j * kGroupX + c is pixel (x0 + c, y0 - radius + j).
void load_tile(ivec2 origin) {
  const int length = kGroupX * (kGroupY + 2 * params.radius);
  for (int i = int(gl_LocalInvocationIndex); i < length; i += kGroupX * kGroupY) {
    const ivec2 q = ivec2(origin.x + i % kGroupX, origin.y - params.radius + i / kGroupX);
    vec3 terms = vec3(0.0);
    if (q.y >= 0 && inside(q, params.width, params.height)) terms = texelFetch(row_means, q, 0).xyz;
    tile_t[i] = terms.x;
    tile_f[i] = terms.y;
    tile_t2[i] = terms.z;
  }
}
#endif

// The window's mean of the three terms, its pixels clamped to the image.
vec3 window_mean(ivec2 p, ivec2 origin) {
#ifdef ROWS
  const int lo = max(p.x - params.radius, 0), hi = min(p.x + params.radius, int(params.width) - 1);
  const int first = lo - (origin.x - params.radius), stride = 1;
#else
  const int lo = max(p.y - params.radius, 0), hi = min(p.y + params.radius, int(params.height) - 1);
  const int first = (lo - (origin.y - params.radius)) * kGroupX + (p.x - origin.x), stride = kGroupX;
#endif
  vec3 sum = vec3(0.0);
  for (int n = 0, i = first; n <= hi - lo; ++n, i += stride) sum += vec3(tile_t[i], tile_f[i], tile_t2[i]);
  return sum / float(hi - lo + 1);
}

// No return in main: one puts the barrier inside the loop construct that inlining makes of it
// (suspected of stalling NVIDIA's OpenGL SPIR-V path: docs/performance.md).
void main() {
  const ivec2 origin = ivec2(gl_WorkGroupID.xy) * ivec2(kGroupX, kGroupY);
  load_tile(origin);
  barrier();
  ivec2 p = invocation_pixel();
  if (inside(p, params.width, params.height)) {
    const vec3 mean = window_mean(p, origin);
#ifdef ROWS
    imageStore(row_means, p, vec4(mean, 0.0));
#else
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
}
