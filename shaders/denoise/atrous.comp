// atrous.comp: one iteration of SVGF's edge-avoiding a-trous wavelet filter (Schied et al. 2017,
// eq. 1-4; the seed's w_z, w_n, w_l). Taps at p + step * (i, j): the 13 of the paper's 5x5
// B3-spline kernel with |i| + |j| <= 2 (the 12 left out hold 14.1% of its weight, and the per-tap
// arithmetic bounds the pass: 17% faster at 1080p than 21 taps, error unchanged, docs/performance.md,
// "Fewer taps") or a 3x3 box (seed), chosen by `kernel`. Colour is averaged with h * w; the
// variance in alpha with (h * w)^2 / (sum h * w)^2. The luminance weight uses the
// 3x3-binomial-prefiltered variance.
// Variants: PACKED_IN reads the packed colour texels (common/filter_texel.glsl) the previous
// iteration wrote to a storage buffer, one per pixel in rows, and the packed surface texels the
// first wrote to another, instead of an RGBA16F colour and depth_normal per tap; PACKED_OUT writes
// colour texels for the next iteration; a chain's last iteration writes RGBA16F for composite.
// PACKED_OUT alone (FIRST_PACKED) is a chain's first iteration (step 1): it also writes the surface
// texels, reads its taps from a shared-memory tile, and estimates each tile texel's colour and
// variance from the temporal pass's output, moments and the albedo (common/variance_estimate.glsl), so the
// variance pass (48 bytes a pixel and a dispatch) does not run. Without PACKED_* (the box kernel,
// one iteration, images too large for packed texels) the first iteration reads the variance pass's
// RGBA16F image. HISTORY also writes the result to the colour history (the history tap), as a
// spatial chain's history is kept: RGB9E5 words (common/color.glsl; temporal.comp's COLOR_RGB9E5). COMPOSITE
// (a one-signal chain's last, packed-in iteration) composites the result (common/composite.glsl),
// unrounded, instead of writing it to an RGBA16F image for the composite pass: 16 bytes a pixel and
// a dispatch fewer (HDR_HALF: its radiance to an RGBA16F image, as composite.comp's). RGB9E5_OUT
// (a packed-in last iteration whose result only the composite reads) writes the colour alone as
// RGB9E5 (common/filter_texel.glsl) to an R32UI image: 4 bytes a pixel written and read instead of 8.
// LOCAL_MEAN_SUMS (the local-mean correction, common/local_mean.glsl) also sums the result's
// luminance over blocks of local_mean_block pixels into block_sums: the first packed iteration with
// the history tap with the temporal result's terms (the history's correction), a packed-in last
// iteration with them taken from temporal_sums (the displayed colour's), so that no pass reads these
// images again to sum them (local_mean.comp's BLOCKS does the same where no iteration can).
// CORRECTS_HISTORY (a packed middle iteration after the history tap) writes the colour history: the
// previous iteration's result corrected toward the temporal result's local mean with the history's
// box means (local_mean.comp), so that the tapped result is not written to an image and read back.
// The surface texel carries the centre's depth gradient in 8 bits (common/filter_texel.glsl), so the
// packed-in iterations read nothing but the two texels.
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#extension GL_EXT_control_flow_attributes : require
#include "common/compute.glsl"
#include "common/denoise.glsl"
#include "common/filter_texel.glsl"

#if defined(PACKED_OUT) && !defined(PACKED_IN)
#define FIRST_PACKED
#endif

#ifdef FIRST_PACKED
// 16x8 (the most invocations OpenGL ES guarantees): the tile's apron, where each texel costs a
// variance estimate, is 0.875 texels a pixel against 1.25 with 8x8.
const int kGroupX = 16;
const int kGroupY = 8;
layout(local_size_x = 16, local_size_y = 8) in;
#elif defined(PACKED_IN) && defined(LOCAL_MEAN_SUMS)
// 16x8: the same 16x2 warps as 16x4 below, and whole blocks of 8 rows.
const int kGroupX = 16;
const int kGroupY = 8;
layout(local_size_x = 16, local_size_y = 8) in;
#elif defined(PACKED_IN)
// 16x4: a warp of 32 covers 16x2 pixels, so a tap's row of 8-byte texels is one whole 128-byte line
// in each buffer; 8x8's 8x4 warps read half lines, twice the requests, which bounded the large steps
// (docs/performance.md).
layout(local_size_x = 16, local_size_y = 4) in;
#else
layout(local_size_x = 8, local_size_y = 8) in;
#endif

layout(set = 0, binding = 0) uniform Params {
  uint width;
  uint height;
  int step;    // 2^iteration
  uint kernel;  // 0: B3 spline, its 13 taps with |i| + |j| <= 2, 1: 3x3 box
  float sigma_z;
  float sigma_n;
  float sigma_l;
  float min_history;  // of the variance estimate (first packed iteration)
  float exposure;     // COMPOSITE: multiplier applied before the tone curve
  uint tonemap;       // COMPOSITE: 0 clamp, 1 ACES (Narkowicz)
  int local_mean_block;   // LOCAL_MEAN_SUMS, CORRECTS_HISTORY: pixels a block's side (1, 2, 4 or 8)
  int local_mean_radius;  // CORRECTS_HISTORY: the correction's window, in blocks
} params;
#ifdef PACKED_IN
layout(set = 0, binding = 1, std430) readonly buffer ColorIn { uvec2 texels[]; } color_in;
layout(set = 0, binding = 5, std430) readonly buffer SurfaceIn { uvec2 texels[]; } surface;
#elif defined(FIRST_PACKED)
layout(set = 0, binding = 1) uniform utexture2D integrated;  // the temporal result's colour, RGB9E5 words
layout(set = 0, binding = 6) uniform utexture2D moments;    // E[l], sqrt(Var[l]), history length: pack_moments
#else
layout(set = 0, binding = 1) uniform texture2D color_in;  // rgb colour, a variance
#endif
#ifndef PACKED_IN
layout(set = 0, binding = 2) uniform utexture2D depth_normal;
#endif
#ifdef PACKED_OUT
layout(set = 0, binding = 3, std430) writeonly buffer ColorOut { uvec2 texels[]; } color_out;
#elif defined(COMPOSITE)
#define ALBEDO_BINDING 7  // float, or RGB9E5 words with ALBEDO_RGB9E5
#include "common/albedo.glsl"
#ifdef HDR_HALF
layout(set = 0, binding = 8, rgba16f) writeonly uniform image2D hdr;
#else
layout(set = 0, binding = 8, rgba32f) writeonly uniform image2D hdr;
#endif
layout(set = 0, binding = 9, rgba8) writeonly uniform image2D display;
// SanitizeCounters (temporal.comp declares the same block): composite counts zeroed_outputs.
layout(set = 0, binding = 10) buffer Counters {
  uint nan_samples;
  uint inf_samples;
  uint clamped_samples;
  uint zeroed_outputs;
} counters;
#include "common/composite.glsl"
#elif defined(RGB9E5_OUT)
layout(set = 0, binding = 3, r32ui) writeonly uniform uimage2D color_out;  // the colour alone
#else
layout(set = 0, binding = 3, rgba16f) writeonly uniform image2D color_out;
#endif
#ifdef HISTORY
layout(set = 0, binding = 4, r32ui) writeonly uniform uimage2D color_history;  // RGB9E5 words
#endif
#ifdef CORRECTS_HISTORY
layout(set = 0, binding = 4, r32ui) writeonly uniform uimage2D color_history;  // RGB9E5 words
layout(set = 0, binding = 13) uniform texture2D box_means;  // the history's correction's (local_mean.comp)
#define LOCAL_MEAN_READS_BOX_MEANS
#include "common/local_mean.glsl"
#endif
#ifdef LOCAL_MEAN_SUMS
// x: temporal, y: this result's, z: temporal squared (luminance sums), w: pixels
layout(set = 0, binding = 11, rgba32f) writeonly uniform image2D block_sums;
#ifdef PACKED_IN
layout(set = 0, binding = 12) uniform texture2D temporal_sums;  // x, z, w: the history's correction's
#endif
#endif
#ifdef FIRST_PACKED
layout(set = 0, binding = 5, std430) writeonly buffer SurfaceOut { uvec2 texels[]; } surface;
#define ALBEDO_BINDING 7  // the variance estimate's (COMPOSITE's binding)
#include "common/albedo.glsl"
#include "common/variance_estimate.glsl"
#endif

ivec2 clamp_pixel(ivec2 q) { return clamp(q, ivec2(0), ivec2(params.width, params.height) - 1); }
// A pixel's texels in the packed buffers (rows).
int texel_index(ivec2 q) { return q.y * int(params.width) + q.x; }

// What a tap reads: colour and variance, depth (0: no hit) and unit normal.
struct Tap {
  vec4 color;
  float z;
  vec3 n;
};
#ifdef FIRST_PACKED
// Step 1 only: the workgroup's 16x8 pixels and their taps lie in one 20x12 block, estimated and
// fetched once into shared memory (colour and variance, decoded normal): 1.9 estimates and normal
// decodes a pixel instead of 25 (docs/performance.md). Entries outside the image hold the nearest
// pixel's values, which is what the variance prefilter's clamped reads want; taps skip them.
const int kApron = 2;
const int kTileX = kGroupX + 2 * kApron;
const int kTileY = kGroupY + 2 * kApron;
shared vec4 tile_color[kTileX * kTileY];  // the variance estimate's colour and variance, unrounded
shared vec4 tile_surface[kTileX * kTileY];  // depth, normal
ivec2 tile_origin() { return ivec2(gl_WorkGroupID.xy) * ivec2(kGroupX, kGroupY) - kApron; }
int tile_index(ivec2 q) {
  const ivec2 t = q - tile_origin();
  return t.y * kTileX + t.x;
}
void load_tile() {
  for (int k = int(gl_LocalInvocationIndex); k < kTileX * kTileY; k += kGroupX * kGroupY) {
    const ivec2 q = clamp_pixel(tile_origin() + ivec2(k % kTileX, k / kTileX));
    const Surface s = surface_from(texelFetch(depth_normal, q, 0));
    tile_color[k] = estimate_color_variance(q, s);
    tile_surface[k] = vec4(s.z, s.n);
  }
}
Tap read_tap(ivec2 q) {
  const int k = tile_index(q);
  const vec4 t = tile_surface[k];
  return Tap(tile_color[k], t.x, t.yzw);
}
float variance_at(ivec2 q) { return tile_color[tile_index(q)].a; }
#elif defined(PACKED_IN)
// Storage-buffer loads, not texel fetches: the fetches' issue rate bounded the iteration
// (docs/performance.md).
Tap read_tap(ivec2 q) {
  const int i = texel_index(q);
  const uvec2 s = surface.texels[i];
  return Tap(unpack_color_halves(color_in.texels[i]), filter_surface_depth(s), filter_surface_normal(s));
}
float variance_at(ivec2 q) { return color_halves_variance(color_in.texels[texel_index(q)]); }
#else
Tap read_tap(ivec2 q) {
  const Surface s = surface_from(texelFetch(depth_normal, q, 0));
  return Tap(texelFetch(color_in, q, 0), s.z, s.n);
}
float variance_at(ivec2 q) { return texelFetch(color_in, q, 0).a; }
#endif

// Whether every tap of every invocation of this workgroup, and so every prefilter read, lies inside
// the image. The same for the whole workgroup, so the taps' bounds tests and the prefilter's clamps
// below become a uniform branch (docs/performance.md). One loop with the test, not a second copy
// without: two copies of the unrolled loop doubled lavapipe's compile time.
bool workgroup_taps_inside() {
  const ivec2 size = ivec2(gl_WorkGroupSize.xy);
  const ivec2 lo = ivec2(gl_WorkGroupID.xy) * size - 2 * params.step;
  const ivec2 hi = ivec2(gl_WorkGroupID.xy + 1u) * size - 1 + 2 * params.step;
  return lo.x >= 0 && lo.y >= 0 && hi.x < int(params.width) && hi.y < int(params.height);
}

float prefiltered_variance(ivec2 p, bool taps_inside) {
  float v = 0.0;
  [[unroll]] for (int dy = -1; dy <= 1; ++dy)
    [[unroll]] for (int dx = -1; dx <= 1; ++dx) {
      const ivec2 q = p + ivec2(dx, dy);
      v += binomial3(dx) * binomial3(dy) * variance_at(taps_inside ? q : clamp_pixel(q));
    }
  return v;
}

// Returns what the fp16 outputs hold.
vec4 filter_pixel(ivec2 p) {
  // The centre's colour, depth and normal come from where the taps' do, so that a tap on the
  // centre's own surface weighs exactly as much.
  const Tap c = read_tap(p);
#ifdef PACKED_IN
  const float dz = filter_surface_gradient(surface.texels[texel_index(p)]);
#else
  const float dz = depth_normal_gradient(texelFetch(depth_normal, p, 0));
#endif
  Surface center = Surface(c.z, dz, c.n);
  vec4 result = c.color;
  if (hit(center)) {
    float lp = luminance(c.color.rgb);
    const bool taps_inside = workgroup_taps_inside();
    float std_dev = sqrt(max(prefiltered_variance(p, taps_inside), 0.0));
    const AtrousScales scales = atrous_scales(center, params.step, params.sigma_z, params.sigma_l, std_dev);
    int radius = params.kernel == 0u ? 2 : 1;
    vec3 sum_c = vec3(0.0);
    float sum_v = 0.0, sum_w = 0.0;
    // Constant bounds (the radius test inside), so that the compiler can unroll and index `scales`.
    [[unroll]] for (int dy = -2; dy <= 2; ++dy) {
      [[unroll]] for (int dx = -2; dx <= 2; ++dx) {
        ivec2 q = p + params.step * ivec2(dx, dy);
        // Unrolled, no `continue`: spirv-opt unrolls only loops without one, and NVIDIA's OpenGL
        // SPIR-V front end keeps a loop as a conditional loop (docs/performance.md).
        // Each axis tested on the side its offset goes (the step is positive, p inside), so that
        // unrolling leaves at most two comparisons a tap.
        const bool x_inside = dx == 0 || (dx < 0 ? q.x >= 0 : q.x < int(params.width));
        const bool y_inside = dy == 0 || (dy < 0 ? q.y >= 0 : q.y < int(params.height));
        if (max(abs(dx), abs(dy)) <= radius && abs(dx) + abs(dy) <= 2 && (taps_inside || (x_inside && y_inside))) {
          float h = params.kernel == 0u ? b3spline(dx) * b3spline(dy) : 1.0;
          const Tap t = (dx == 0 && dy == 0) ? c : read_tap(q);
          float w = h;
          if (dx != 0 || dy != 0)
            w *= atrous_tap_weight(center, lp, t.z, t.n, luminance(t.color.rgb), abs(dx) + abs(dy), params.sigma_n, scales);
          sum_c += w * t.color.rgb;
          sum_v += w * w * t.color.a;
          sum_w += w;
        }
      }
    }
    result = vec4(sum_c / sum_w, sum_v / (sum_w * sum_w));
  }
  result = clamp_fp16(result);
  const vec4 stored = round_to_half_clamped(result);  // what every fp16 output below holds (common/color.glsl)
#ifdef PACKED_OUT
  color_out.texels[texel_index(p)] = pack_color_halves(result);
#ifdef FIRST_PACKED
  surface.texels[texel_index(p)] = pack_filter_surface(center.z, dz, center.n);
#endif
#elif defined(COMPOSITE)
  composite_pixel(p, result.rgb);
#elif defined(RGB9E5_OUT)
  imageStore(color_out, p, uvec4(pack_rgb9e5(result.rgb), 0u, 0u, 0u));
#else
  imageStore(color_out, p, stored);
#endif
#ifdef HISTORY
  imageStore(color_history, p, uvec4(pack_rgb9e5(result.rgb), 0u, 0u, 0u));
#endif
#ifdef CORRECTS_HISTORY
  // The previous iteration's result, this one's centre texel, corrected toward the temporal result's
  // local mean (the plain ratio) is the colour history: local_mean.comp's last pass without the
  // image that pass would read and write.
  const float scale =
      local_mean_scale(p, ivec2(params.width, params.height), params.local_mean_block, params.local_mean_radius, false);
  imageStore(color_history, p, uvec4(local_mean_corrected_rgb9e5(c.color.rgb, scale), 0u, 0u, 0u));
#endif
  return stored;
}

#ifdef LOCAL_MEAN_SUMS
#define LOCAL_MEAN_GROUP_X kGroupX
#define LOCAL_MEAN_GROUP_Y kGroupY
#ifdef FIRST_PACKED
// The block sums in the tile's shared memory, which the filter no longer reads: 4 KB a workgroup
// more (less L1 beside the shared memory) had cost the first iteration 0.026 ms at 1080p on an H100,
// 0.035 on OpenGL (docs/performance.md, "The local mean's cost, measured").
#define LOCAL_MEAN_TERMS tile_color
#define LOCAL_MEAN_ROWS tile_surface
#else
// The last iteration sums its own luminance alone (the temporal terms are the history's sums).
#define LOCAL_MEAN_SUM_TYPE float
#endif
#include "common/local_mean.glsl"
#endif

// No return in main: one puts the barrier inside the loop construct that inlining makes of it
// (suspected of stalling NVIDIA's OpenGL SPIR-V path: docs/performance.md).
void main() {
#ifdef FIRST_PACKED
  load_tile();
  barrier();
#endif
  ivec2 p = invocation_pixel();
#ifdef LOCAL_MEAN_SUMS
  LOCAL_MEAN_SUM_TYPE terms = LOCAL_MEAN_SUM_TYPE(0.0);
  if (inside(p, params.width, params.height)) {
    const float l = luminance(filter_pixel(p).rgb);
#ifdef FIRST_PACKED
    const float lt = luminance(integrated_color(p));
    terms = vec4(lt, l, lt * lt, 1.0);
#else
    terms = l;
#endif
  }
  const LOCAL_MEAN_SUM_TYPE sum = local_mean_block_sum(terms, params.local_mean_block);
  const ivec2 q = p / params.local_mean_block;
  const ivec2 size = ivec2(params.width, params.height);
  if (local_mean_block_first(params.local_mean_block) && all(lessThan(q, local_mean_blocks(size, params.local_mean_block)))) {
#ifdef PACKED_IN
    const vec4 ts = texelFetch(temporal_sums, q, 0);
    imageStore(block_sums, q, vec4(ts.x, sum, ts.zw));
#else
    imageStore(block_sums, q, sum);
#endif
  }
#else
  if (inside(p, params.width, params.height)) filter_pixel(p);
#endif
}
