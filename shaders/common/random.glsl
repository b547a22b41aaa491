// common/random.glsl: per-pixel random numbers from a 32-bit state (PCG hash, O'Neill 2014, as
// popularised by Jarzynski & Olano, "Hash Functions for GPU Rendering", JCGT 2020).
#ifndef ASVGF_COMMON_RANDOM_GLSL
#define ASVGF_COMMON_RANDOM_GLSL

uint pcg_hash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

// A seed that is never 0: pathtrace stores 0 for a pixel that shaded a carried gradient sample.
uint pixel_seed(uvec2 pixel, uint width, uint frame, uint global_seed) {
  uint s = pcg_hash(pixel.y * width + pixel.x + pcg_hash(frame + pcg_hash(global_seed)));
  return s == 0u ? 1u : s;
}

// Uniform in [0, 1): advances the state.
float next_random(inout uint state) {
  state = pcg_hash(state);
  return float(state >> 8u) * (1.0 / 16777216.0);
}

#endif
