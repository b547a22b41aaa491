// gradient_clear: resets this frame's gradient-sample outputs before gradient_select fills some of
// them: per 3x3 stratum no sample (gradient_prev.y = -1) and no claim. The seed image is not
// cleared: pathtrace reads a stratum's seed only where gradient_prev.y names the pixel (a
// full-resolution clear ran at 2.8x its traffic floor, docs/performance.md).
#version 460
#extension GL_GOOGLE_include_directive : require

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, std140) uniform Params {
  uint width;
  uint height;
  uint strata_width;
  uint strata_height;
} params;

layout(set = 0, binding = 1, std430) writeonly buffer Claims { uint values[]; } claims;
layout(set = 0, binding = 2, rgba32f) writeonly uniform image2D gradient_prev;  // rgba: ESSL 310 has no rg formats

// One invocation a stratum.
void main() {
  ivec2 s = ivec2(gl_GlobalInvocationID.xy);
  if (s.x >= int(params.strata_width) || s.y >= int(params.strata_height)) return;
  claims.values[s.y * int(params.strata_width) + s.x] = 0xFFFFFFFFu;  // no bid yet
  imageStore(gradient_prev, s, vec4(0.0, -1.0, 0.0, 0.0));
}
