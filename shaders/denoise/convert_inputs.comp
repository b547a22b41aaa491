// convert_inputs.comp: a renderer's buffers in its own conventions as the denoiser's (the public
// API's first pass where they differ, asvgf::DenoiserConfig::color_input and ::motion).
//  - Radiance in (color_is_radiance = 1): illumination = radiance / max(a, kMinAlbedo) and the albedo
//    the composite re-modulates by (the same guard) = a, an RGB9E5 word (4 bytes a pixel; divided by
//    its own value, so re-modulation gives back the radiance: common/albedo.glsl), per channel, with
//    a = albedo where albedo >= kMinAlbedo, else 1 (where a surface has no albedo to divide by, e.g.
//    a black or an emitting one whose renderer writes 0, the radiance passes through unfiltered by
//    texture). An emitter whose albedo holds its emission (Cycles' Denoising Albedo) is divided by
//    it and multiplied back.
//  - Motion: m = scale * v per axis (asvgf::motion_scale: the sign, UV or NDC units to pixels, y up
//    to down). The result is previous minus current position, in pixels, y down.
// CPU twin: reference::convert_inputs (pipeline/cpu_oracle/denoise_reference.cpp).
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#include "common/color.glsl"
#include "common/compute.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform Params {
  uint width;
  uint height;
  uint color_is_radiance;  // 1: color is radiance (divide by the albedo); 0: already demodulated
  float motion_scale_x;    // pixels per unit of the renderer's vectors, negative where they point forward
  float motion_scale_y;    // likewise, and negated where the renderer's y points up
  uint pad0;
  uint pad1;
  uint pad2;
} params;
layout(set = 0, binding = 1) uniform texture2D color;
layout(set = 0, binding = 2) uniform texture2D albedo;
layout(set = 0, binding = 3) uniform texture2D motion;
layout(set = 0, binding = 4, rgba32f) writeonly uniform image2D illumination;
layout(set = 0, binding = 5, r32ui) writeonly uniform uimage2D modulation;  // RGB9E5 words
layout(set = 0, binding = 6, rgba32f) writeonly uniform image2D motion_out;

const float kMinAlbedo = 1e-3;

void main() {
  ivec2 p = invocation_pixel();
  if (!inside(p, params.width, params.height)) return;
  vec3 c = texelFetch(color, p, 0).rgb;
  vec3 a = texelFetch(albedo, p, 0).rgb;
  vec3 m = vec3(1.0);
  if (params.color_is_radiance != 0u) {
    // NaN and negative albedos count as none (the validator reports them); the sample stays as it
    // is, NaN included, for the temporal pass to drop and count.
    for (int i = 0; i < 3; ++i) m[i] = a[i] >= kMinAlbedo && !not_finite(a[i]) ? a[i] : 1.0;
    const uint word = pack_rgb9e5(m);
    c /= max(unpack_rgb9e5(word), vec3(kMinAlbedo));  // composite's guard (common/composite.glsl)
    imageStore(modulation, p, uvec4(word));
  }  // else the caller's albedo is re-modulated by as it is (modulation is not read)
  imageStore(illumination, p, vec4(c, 0.0));
  vec2 v = texelFetch(motion, p, 0).xy;
  imageStore(motion_out, p, vec4(vec2(params.motion_scale_x, params.motion_scale_y) * v, 0.0, 0.0));
}
