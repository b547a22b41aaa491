// accumulate: progressive reference. Running mean of this frame's samples with last frame's mean
// (weighted by sample counts), restarted when the scene changed (history_valid = 0).
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, std140) uniform Params {
  uint width;
  uint height;
  uint history_valid;
  uint pad;
} params;

layout(set = 0, binding = 1) uniform texture2D illumination;
layout(set = 0, binding = 2) uniform texture2D prev_accumulation;
layout(set = 0, binding = 3, rgba32f) writeonly uniform image2D accumulation;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= int(params.width) || p.y >= int(params.height)) return;
  vec3 current = texelFetch(illumination, p, 0).rgb;
  vec4 previous = params.history_valid != 0u ? texelFetch(prev_accumulation, p, 0) : vec4(0.0);
  float n = previous.a;  // frames accumulated so far
  vec3 mean = (previous.rgb * n + current) / (n + 1.0);
  imageStore(accumulation, p, vec4(mean, n + 1.0));
}
