// Portable: an r32f image both read and written, and an SSBO both read and written (read_write
// storage buffers are fine on every target). The tool must accept it.
#version 460
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, r32f) uniform image2D accum;
layout(set = 0, binding = 1) buffer Counters { uint values[]; } counters;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  imageStore(accum, p, imageLoad(accum, p) + vec4(1.0));
  counters.values[p.x] += 1u;
}
