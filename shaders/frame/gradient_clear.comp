// gradient_clear: resets this frame's gradient-sample outputs before gradient_select fills some of
// them: per 3x3 stratum no sample (gradient_prev.y = -1) and no claim; no carried seed anywhere.
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
layout(set = 0, binding = 2, rgba32ui) writeonly uniform uimage2D gradient_seeds;
layout(set = 0, binding = 3, rgba32f) writeonly uniform image2D gradient_prev;  // rgba: ESSL 310 has no rg formats

// One invocation a pixel: stores to neighbouring pixels coalesce (an invocation a stratum writing
// its 3x3 pixels ran at 7.5x the traffic floor on the H200). The stratum's corner pixel resets the
// stratum's claim and sample.
void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= int(params.width) || p.y >= int(params.height)) return;
  imageStore(gradient_seeds, p, uvec4(0u));
  ivec2 s = p / 3;
  if (p != 3 * s) return;
  claims.values[s.y * int(params.strata_width) + s.x] = 0xFFFFFFFFu;  // no bid yet
  imageStore(gradient_prev, s, vec4(0.0, -1.0, 0.0, 0.0));
}
