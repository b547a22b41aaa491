// common/sampling.glsl: directions and points for Monte Carlo estimators.
#ifndef ASVGF_COMMON_SAMPLING_GLSL
#define ASVGF_COMMON_SAMPLING_GLSL

const float kPi = 3.14159265358979;

// An orthonormal basis around n (Duff et al., "Building an Orthonormal Basis, Revisited", 2017).
void basis(vec3 n, out vec3 t, out vec3 b) {
  float s = n.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (s + n.z);
  float c = n.x * n.y * a;
  t = vec3(1.0 + s * n.x * n.x * a, s * c, -s * n.x);
  b = vec3(c, s + n.y * n.y * a, -n.y);
}

// Cosine-weighted direction about n; pdf = cos(theta) / pi.
vec3 sample_cosine(vec3 n, float u1, float u2) {
  float r = sqrt(u1);
  float phi = 2.0 * kPi * u2;
  vec3 t, b;
  basis(n, t, b);
  return normalize(r * cos(phi) * t + r * sin(phi) * b + sqrt(max(0.0, 1.0 - u1)) * n);
}

// Direction inside the cone subtended by a sphere (uniform in solid angle). Returns the pdf (per
// solid angle) in w; w = 0 when x is inside the sphere.
// One return in this and the next (see common/trace.glsl's intersect_triangle).
vec4 sample_sphere_cone(vec3 x, vec3 centre, float radius, float u1, float u2) {
  vec3 to = centre - x;
  float d2 = dot(to, to);
  vec4 result = vec4(0.0);
  if (!(d2 <= radius * radius)) {
    float cos_max = sqrt(max(0.0, 1.0 - radius * radius / d2));
    float cos_theta = 1.0 - u1 * (1.0 - cos_max);
    float sin_theta = sqrt(max(0.0, 1.0 - cos_theta * cos_theta));
    float phi = 2.0 * kPi * u2;
    vec3 w = to / sqrt(d2);
    vec3 t, b;
    basis(w, t, b);
    vec3 dir = normalize(sin_theta * cos(phi) * t + sin_theta * sin(phi) * b + cos_theta * w);
    result = vec4(dir, 1.0 / (2.0 * kPi * (1.0 - cos_max)));
  }
  return result;
}

// Solid-angle pdf of sample_sphere_cone for any direction that hits the sphere.
float sphere_cone_pdf(vec3 x, vec3 centre, float radius) {
  vec3 to = centre - x;
  float d2 = dot(to, to);
  float cos_max = sqrt(max(0.0, 1.0 - radius * radius / d2));
  return d2 <= radius * radius ? 0.0 : 1.0 / (2.0 * kPi * (1.0 - cos_max));
}

// Uniform point on a triangle (barycentric weights of p1, p2).
vec2 sample_triangle(float u1, float u2) {
  float s = sqrt(u1);
  return vec2(s * (1.0 - u2), s * u2);
}

// Power heuristic with beta = 2 (Veach 1997).
float power_heuristic(float a, float b) {
  float a2 = a * a;
  return a2 / max(a2 + b * b, 1e-30);
}

#endif
