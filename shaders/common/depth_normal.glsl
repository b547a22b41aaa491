// common/depth_normal.glsl: the G-buffer's surface texel, RGBA16UI (8 bytes, half of the RGBA32F
// it replaces): every pass that reads the G-buffer reads it, the temporal pass twice (this frame's
// and last frame's). Two 32-bit words, w0 = x | y << 16 and w1 = z | w << 16:
//   w0 bits 8-31  the linear view depth's fp32 bits, rounded to 24 (within 2^-16 of it; 0: no hit)
//   w0 bits 0-7   the octahedral normal's x (common/octahedral.glsl) as snorm12, its high 8 bits
//   w1 bits 28-31 x's low 4 bits
//   w1 bits 16-27 the octahedral y as snorm12 (k - 2048 = round(2047 y): 0 and +-1 exact)
//   w1 bits 0-15  the depth gradient max(|dz/dx|, |dz/dy|) as bfloat16 (fp32's high half, rounded:
//                 a relative step of 2^-8 over fp32's whole range, so no scale loses it)
// Each rounding is far inside what it feeds: the depth weight's tolerance is at least 1e-3 of the
// depth, a normal moves by at most about 0.03 degrees, and the gradient only scales a tolerance.
// Equal inputs pack equal. CPU twin: asvgf::reference::pack_depth_normal / unpack_depth_normal
// (pipeline/cpu_oracle/depth_normal.hpp).
#ifndef ASVGF_COMMON_DEPTH_NORMAL_GLSL
#define ASVGF_COMMON_DEPTH_NORMAL_GLSL

#include "common/octahedral.glsl"

uint snorm12(float e) { return uint(int(floor(clamp(e, -1.0, 1.0) * 2047.0 + 0.5)) + 2048); }
float from_snorm12(uint k) { return (float(k) - 2048.0) / 2047.0; }

// z > 0 (else the texel is all 0: no hit), dz >= 0 finite, n not zero (need not be unit).
uvec4 pack_depth_normal(float z, float dz, vec3 n) {
  if (!(z > 0.0)) return uvec4(0u);
  const uint zq = (floatBitsToUint(z) + 0x80u) & 0xffffff00u;
  const vec2 e = oct_encode(n);
  const uint ex = snorm12(e.x), ey = snorm12(e.y);
  const uint w0 = zq | (ex >> 4);
  const uint w1 = ((ex & 0xfu) << 28) | (ey << 16) | ((floatBitsToUint(dz) + 0x8000u) >> 16);
  return uvec4(w0 & 0xffffu, w0 >> 16, w1 & 0xffffu, w1 >> 16);
}
float depth_normal_depth(uvec4 t) { return uintBitsToFloat((t.x | (t.y << 16)) & 0xffffff00u); }
float depth_normal_gradient(uvec4 t) { return uintBitsToFloat(t.z << 16); }
vec2 depth_normal_oct(uvec4 t) {
  return vec2(from_snorm12(((t.x & 0xffu) << 4) | (t.w >> 12)), from_snorm12(t.w & 0xfffu));
}
vec3 depth_normal_normal(uvec4 t) { return oct_decode(depth_normal_oct(t)); }

#endif
