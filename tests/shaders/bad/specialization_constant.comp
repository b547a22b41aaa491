// Breaks a portability rule: a specialization constant (HAL pipelines take no specializations).
#version 460
layout(local_size_x = 64) in;
layout(constant_id = 0) const float kScale = 2.0;
layout(set = 0, binding = 0) writeonly buffer Output { float values[]; } dst;

void main() { dst.values[gl_GlobalInvocationID.x] = kScale; }
