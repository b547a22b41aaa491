// export_aovs.comp: the frame's G-buffer as the denoiser's public inputs (include/asvgf/denoiser.hpp),
// for `asvgf render --aovs`: depth = (linear view depth, depth gradient) and normal = world-space
// unit normal from the depth_normal texel (the inverse of denoise/pack_surface.comp; background
// stays all zero), and the albedo (RGB9E5 words: what the path tracer divided by) as RGBA32F.
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
layout(set = 0, binding = 1) uniform utexture2D depth_normal;
#define ALBEDO_RGB9E5  // the G-buffer's (gbuffer.comp)
#define ALBEDO_BINDING 2
#include "common/albedo.glsl"
layout(set = 0, binding = 3, rgba32f) writeonly uniform image2D depth_out;
layout(set = 0, binding = 4, rgba32f) writeonly uniform image2D normal_out;
layout(set = 0, binding = 5, rgba32f) writeonly uniform image2D albedo_out;

void main() {
  ivec2 p = invocation_pixel();
  if (!inside(p, params.width, params.height)) return;
  Surface s = surface_from(texelFetch(depth_normal, p, 0));
  bool h = hit(s);
  imageStore(depth_out, p, h ? vec4(s.z, s.dz, 0.0, 0.0) : vec4(0.0));
  imageStore(normal_out, p, h ? vec4(s.n, 0.0) : vec4(0.0));
  imageStore(albedo_out, p, vec4(albedo_at(p), 1.0));
}
