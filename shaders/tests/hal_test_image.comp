// hal_test_image.comp: dst_image = texelFetch(src_image) * scale + offset inside width x height.
// Used by the Vulkan backend's tests; reads through texture2D + texelFetch as DESIGN.md asks.
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#include "common/compute.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform Params {
  uint width;
  uint height;
  float scale;
  float offset;
} params;
layout(set = 0, binding = 1) uniform texture2D src_image;
layout(set = 0, binding = 2, rgba32f) writeonly uniform image2D dst_image;

void main() {
  ivec2 p = invocation_pixel();
  if (!inside(p, params.width, params.height)) return;
  imageStore(dst_image, p, texelFetch(src_image, p, 0) * params.scale + params.offset);
}
