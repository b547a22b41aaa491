// unpack_surface.comp: the frame's depth_normal texel as the denoiser's public inputs (the inverse of
// denoise/pack_surface.comp), for `asvgf render --aovs`: depth = (linear view depth, depth gradient),
// normal = world-space unit normal; background stays all zero.
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#include "common/compute.glsl"
#include "common/denoise.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform Params {
  uint width;
  uint height;
} params;
layout(set = 0, binding = 1) uniform texture2D depth_normal;
layout(set = 0, binding = 2, rgba32f) writeonly uniform image2D depth;
layout(set = 0, binding = 3, rgba32f) writeonly uniform image2D normal;

void main() {
  ivec2 p = invocation_pixel();
  if (!inside(p, params.width, params.height)) return;
  Surface s = surface_from(texelFetch(depth_normal, p, 0));
  bool h = hit(s);
  imageStore(depth, p, h ? vec4(s.z, s.dz, 0.0, 0.0) : vec4(0.0));
  imageStore(normal, p, h ? vec4(s.n, 0.0) : vec4(0.0));
}
