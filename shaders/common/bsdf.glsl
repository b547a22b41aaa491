// common/bsdf.glsl: the glossy surface model, glTF's metallic-roughness BRDF (glTF 2.0 spec,
// appendix B) with KHR_materials_specular's factor: a GGX microfacet lobe (Walter et al. 2007) with
// height-correlated Smith masking-shadowing (Heitz 2014) and Schlick's Fresnel, over a Lambertian
// lobe weighted by what the dielectric Fresnel leaves. Sampled by the GGX distribution of visible
// normals (Heitz 2018, "Sampling the GGX Distribution of Visible Normals", JCGT 7(4)) or the cosine,
// one lobe chosen per sample, so the pdf is the lobes' mixture. CPU twin: pipeline/cpu_oracle/bsdf.hpp.
//
// Parameters: base colour c, metallic m, roughness r (alpha = r^2), specular s.
//   F_dielectric(x) = s (0.04 + 0.96 (1 - x)^5)    F_metal(x) = c + (1 - c)(1 - x)^5
//   F = mix(F_dielectric, F_metal, m)
//   f = F(v.h) D(h) G2(v, l) / (4 n.v n.l) + (1 - m) (1 - F_dielectric(n.v)) c / pi
// s = 0 and m = 0 is the plain Lambertian surface, traced by the path tracer's diffuse-only code.
#ifndef ASVGF_COMMON_BSDF_GLSL
#define ASVGF_COMMON_BSDF_GLSL

#include "common/sampling.glsl"
#include "common/scene_data.glsl"  // luminance()

// No delta lobes: smoother surfaces are traced as alpha = kMinAlpha (roughness 0.045), whose GGX
// peak D = 1 / (pi alpha^2) ~ 8e4 stays far inside float range.
const float kMinAlpha = 0.002;
const float kDielectricF0 = 0.04;  // glTF's IOR 1.5

struct Glossy {
  vec3 base;
  float metallic;
  float alpha;
  float specular;
};

bool is_glossy(float metallic, float specular) { return metallic > 0.0 || specular > 0.0; }
Glossy make_glossy(vec3 base, float roughness, float metallic, float specular) {
  return Glossy(base, metallic, max(roughness * roughness, kMinAlpha), specular);
}

float schlick_weight(float x) {
  float k = 1.0 - clamp(x, 0.0, 1.0);
  float k2 = k * k;
  return k2 * k2 * k;
}
float fresnel_dielectric(Glossy g, float x) { return g.specular * (kDielectricF0 + (1.0 - kDielectricF0) * schlick_weight(x)); }
vec3 fresnel(Glossy g, float x) {
  vec3 metal = g.base + (1.0 - g.base) * schlick_weight(x);
  return mix(vec3(fresnel_dielectric(g, x)), metal, g.metallic);
}
vec3 diffuse_weight(Glossy g, float n_v) { return (1.0 - g.metallic) * (1.0 - fresnel_dielectric(g, n_v)) * g.base; }

// h in the frame n = z. cos^2 (a2 - 1) + 1 is written a2 cos^2 + sin^2 with sin^2 from h.xy: near
// the peak 1 - cos^2 cancels in float and would cost ~3% of D at the smallest alpha.
float ggx_d(vec3 h, float alpha) {
  float a2 = alpha * alpha;
  float k = a2 * h.z * h.z + dot(h.xy, h.xy);
  return a2 / (kPi * k * k);
}
// Smith's Lambda for GGX at cos(theta) = mu > 0.
float ggx_lambda(float mu, float alpha) {
  float tan2 = max(1.0 - mu * mu, 0.0) / (mu * mu);
  return 0.5 * (sqrt(1.0 + alpha * alpha * tan2) - 1.0);
}

// The probability of choosing the GGX lobe: its Fresnel weight against the diffuse one, kept in
// [0.1, 0.9] when both exist so that neither lobe is starved.
float glossy_lobe_probability(Glossy g, float n_v) {
  float s = luminance(fresnel(g, n_v));
  float d = luminance(diffuse_weight(g, n_v));
  return d <= 0.0 ? 1.0 : clamp(s / (s + d), 0.1, 0.9);
}

// f(v, l) cos(theta_l) and the sampling pdf of l (per solid angle), in the frame where n = z; v and l
// are unit vectors there with v.z > 0. `specular`: the GGX lobe's part of the result (the rest is
// the diffuse lobe's), for the path tracer's split into diffuse and specular signals.
// One return (see common/trace.glsl's intersect_triangle).
vec3 glossy_f_cos(Glossy g, vec3 v, vec3 l, out float pdf, out vec3 specular) {
  pdf = 0.0;
  specular = vec3(0.0);
  vec3 result = vec3(0.0);
  if (!(l.z <= 0.0 || v.z <= 0.0)) {
    vec3 h = normalize(v + l);
    float d = ggx_d(h, g.alpha);
    float lambda_v = ggx_lambda(v.z, g.alpha);
    float g2 = 1.0 / (1.0 + lambda_v + ggx_lambda(l.z, g.alpha));
    vec3 spec = fresnel(g, dot(v, h)) * (d * g2 / (4.0 * v.z));  // times l.z / l.z
    vec3 diff = diffuse_weight(g, v.z) * (l.z / kPi);
    float p = glossy_lobe_probability(g, v.z);
    pdf = p * d / (4.0 * v.z * (1.0 + lambda_v)) + (1.0 - p) * l.z / kPi;
    specular = spec;
    result = spec + diff;
  }
  return result;
}

// A direction l (frame n = z) from three uniform numbers; l.z <= 0 means the sample left the
// hemisphere (the path ends there).
// One return (see common/trace.glsl's intersect_triangle).
vec3 glossy_sample(Glossy g, vec3 v, float u0, float u1, float u2) {
  vec3 l;
  if (u0 >= glossy_lobe_probability(g, v.z)) {
    float r = sqrt(u1);
    float phi = 2.0 * kPi * u2;
    l = vec3(r * cos(phi), r * sin(phi), sqrt(max(0.0, 1.0 - u1)));
  } else {
    // Visible normals: stretch the view to the unit-roughness configuration, sample the projected
    // disk of the hemisphere it sees, unstretch.
    vec3 vh = normalize(vec3(g.alpha * v.x, g.alpha * v.y, v.z));
    float len2 = vh.x * vh.x + vh.y * vh.y;
    vec3 t1 = len2 > 0.0 ? vec3(-vh.y, vh.x, 0.0) * inversesqrt(len2) : vec3(1.0, 0.0, 0.0);
    vec3 t2 = cross(vh, t1);
    float r = sqrt(u1);
    float phi = 2.0 * kPi * u2;
    float p1 = r * cos(phi);
    float p2 = r * sin(phi);
    float s = 0.5 * (1.0 + vh.z);
    p2 = (1.0 - s) * sqrt(max(0.0, 1.0 - p1 * p1)) + s * p2;
    vec3 nh = p1 * t1 + p2 * t2 + sqrt(max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
    vec3 h = normalize(vec3(g.alpha * nh.x, g.alpha * nh.y, max(nh.z, 0.0)));
    l = reflect(-v, h);
  }
  return l;
}

// The GGX lobe's directional albedo seen from n.v by Karis's fit of the split-sum table
// ("Physically Based Shading on Mobile", 2014; Lazarov 2013), with F90 = mix(s, 1, m). The fit
// dips slightly below 0 near roughness 1 (about -0.002): callers clamp.
vec3 glossy_specular_albedo_fit(Glossy g, float roughness, float n_v) {
  vec4 r = roughness * vec4(-1.0, -0.0275, -0.572, 0.022) + vec4(1.0, 0.0425, 1.04, -0.04);
  float a004 = min(r.x * r.x, exp2(-9.28 * n_v)) * r.x + r.y;
  vec2 ab = vec2(-1.04, 1.04) * a004 + r.zw;
  vec3 f0 = mix(vec3(g.specular * kDielectricF0), g.base, g.metallic);
  float f90 = mix(g.specular, 1.0, g.metallic);
  return f0 * ab.x + f90 * ab.y;
}

// What the denoiser demodulates a glossy surface by when it filters one signal: its directional
// albedo seen from n.v, the diffuse part exactly and the GGX part by the fit above (a dark metal
// must not get a negative albedo).
vec3 glossy_albedo(Glossy g, float roughness, float n_v) {
  return max(diffuse_weight(g, n_v) + glossy_specular_albedo_fit(g, roughness, n_v), vec3(0.0));
}

#endif
