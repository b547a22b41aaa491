// hal_test_half_store.comp: stores each texel of `values` into three RGBA16F images: `rounded`
// through common/color.glsl's round_to_half, `rounded_clamped` through round_to_half_clamped (the
// values clamped to the fp16 range first), `native` as the device's store converts it (whose
// rounding the conformance test reports).
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#include "common/compute.glsl"
#include "common/color.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform Params {
  uint width;
  uint height;
} params;
layout(set = 0, binding = 1) uniform texture2D values;
layout(set = 0, binding = 2, rgba16f) writeonly uniform image2D rounded;
layout(set = 0, binding = 3, rgba16f) writeonly uniform image2D native;
layout(set = 0, binding = 4, rgba16f) writeonly uniform image2D rounded_clamped;

void main() {
  ivec2 p = invocation_pixel();
  if (!inside(p, params.width, params.height)) return;
  const vec4 v = texelFetch(values, p, 0);
  imageStore(rounded, p, round_to_half(v));
  imageStore(native, p, v);
  imageStore(rounded_clamped, p, round_to_half_clamped(clamp_fp16(v)));
}
