// cache_latency: the first invocation of each workgroup follows a chain of indices, each load's
// address the last load's value, through a storage buffer (default) or a sampled image
// (CHASE_IMAGE): `asvgf bench --cache-latency` times it for growing chains to show where the cache
// each kind of load goes through ends (a backend whose buffer loads skip a cache its images use,
// or get less of it, shows it here first).
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require

layout(local_size_x = 32) in;

layout(set = 0, binding = 0, std140) uniform Params {
  uint steps;        // dependent loads per chain
  uint start_step;   // workgroup w starts at chain element (w * start_step) mod elements
  uint width_shift;  // the image's width is 1 << width_shift texels
  uint elements;     // elements in the chain
} params;
#ifdef CHASE_IMAGE
layout(set = 0, binding = 1) uniform utexture2D chain;
#else
layout(set = 0, binding = 1, std430) readonly buffer Chain { uint values[]; } chain;
#endif
// Each workgroup's last index: the loads cannot be dropped, and a test can check the walk.
layout(set = 0, binding = 2, std430) writeonly buffer Ends { uint values[]; } ends;

// The chain's elements are 32 words (128 bytes, a cache line) apart: element e at word 32 e.
uint next_word(uint word) {
#ifdef CHASE_IMAGE
  uint mask = (1u << params.width_shift) - 1u;
  return texelFetch(chain, ivec2(int(word & mask), int(word >> params.width_shift)), 0).x;
#else
  return chain.values[word];
#endif
}

void main() {
  if (gl_LocalInvocationIndex != 0u) return;
  uint word = 32u * ((gl_WorkGroupID.x * params.start_step) % params.elements);
  for (uint s = 0u; s < params.steps; ++s) word = next_word(word);
  ends.values[gl_WorkGroupID.x] = word;
}
