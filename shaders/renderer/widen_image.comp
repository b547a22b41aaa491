// widen_image.comp: copies a float image of any format into an RGBA32F one of the same size (what
// a transfer copy cannot do between formats of different texel sizes), for `asvgf render --aovs`:
// the half-float illumination and motion exported as the public API's RGBA32F. SOURCE_HALVES: the
// source is R32UI, two halves a word (the G-buffer's motion, common/motion.glsl), widened to (x, y, 0, 0).
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#include "common/compute.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform Params {
  uint width;
  uint height;
} params;
#ifdef SOURCE_HALVES
layout(set = 0, binding = 1) uniform utexture2D source;
#else
layout(set = 0, binding = 1) uniform texture2D source;
#endif
layout(set = 0, binding = 2, rgba32f) writeonly uniform image2D target;

void main() {
  ivec2 p = invocation_pixel();
  if (!inside(p, params.width, params.height)) return;
#ifdef SOURCE_HALVES
  imageStore(target, p, vec4(unpackHalf2x16(texelFetch(source, p, 0).x), 0.0, 0.0));
#else
  imageStore(target, p, texelFetch(source, p, 0));
#endif
}
