// A uniform block of a vec4 and one uint: 20 bytes in std140, 32 in WGSL (its alignment is 16), so
// WebGPU would refuse the HAL's 20-byte binding.
#version 460
layout(local_size_x = 64) in;
layout(set = 0, binding = 0) uniform Params {
  vec4 scale;
  uint count;
} params;
layout(set = 0, binding = 1, std430) buffer Data { vec4 values[]; } data;
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < params.count) data.values[i] = data.values[i] * params.scale;
}
