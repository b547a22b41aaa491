// cpu_oracle/bsdf.hpp: the C++ twin (double precision) of shaders/common/bsdf.glsl's BRDF value,
// and its directional albedo by quadrature: what a white furnace must show.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace asvgf::reference {

using Vec3 = std::array<double, 3>;

struct GlossyMaterial {
  Vec3 base{1, 1, 1};
  double roughness = 1;
  double metallic = 0;
  double specular = 0;
};

inline constexpr double kMinAlpha = 0.002;
inline constexpr double kDielectricF0 = 0.04;

inline double glossy_alpha(const GlossyMaterial& m) { return std::max(m.roughness * m.roughness, kMinAlpha); }
inline double schlick_weight(double x) { return std::pow(1.0 - std::clamp(x, 0.0, 1.0), 5.0); }
inline double fresnel_dielectric(const GlossyMaterial& m, double x) {
  return m.specular * (kDielectricF0 + (1.0 - kDielectricF0) * schlick_weight(x));
}
inline double ggx_d(double n_h, double alpha) {
  const double a2 = alpha * alpha;
  const double k = n_h * n_h * (a2 - 1.0) + 1.0;
  return a2 / (std::numbers::pi * k * k);
}
inline double ggx_lambda(double mu, double alpha) {
  const double tan2 = std::max(1.0 - mu * mu, 0.0) / (mu * mu);
  return 0.5 * (std::sqrt(1.0 + alpha * alpha * tan2) - 1.0);
}

// f(v, l) cos(theta_l) in the frame n = z (v, l unit, v.z > 0); 0 below the horizon.
inline Vec3 glossy_f_cos(const GlossyMaterial& m, const Vec3& v, const Vec3& l) {
  if (l[2] <= 0.0 || v[2] <= 0.0) return {0, 0, 0};
  Vec3 h{v[0] + l[0], v[1] + l[1], v[2] + l[2]};
  const double len = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
  for (double& c : h) c /= len;
  const double alpha = glossy_alpha(m);
  const double v_h = v[0] * h[0] + v[1] * h[1] + v[2] * h[2];
  const double g2 = 1.0 / (1.0 + ggx_lambda(v[2], alpha) + ggx_lambda(l[2], alpha));
  const double spec = ggx_d(h[2], alpha) * g2 / (4.0 * v[2]);
  const double f_d = fresnel_dielectric(m, v_h);
  const double diffuse = (1.0 - m.metallic) * (1.0 - fresnel_dielectric(m, v[2])) * l[2] / std::numbers::pi;
  Vec3 out{};
  for (int c = 0; c < 3; ++c) {
    const double f_metal = m.base[c] + (1.0 - m.base[c]) * schlick_weight(v_h);
    const double f = f_d + (f_metal - f_d) * m.metallic;
    out[c] = f * spec + diffuse * m.base[c];
  }
  return out;
}

// The BRDF's directional albedo at cos(theta_v) = mu_v: the integral of f cos over the hemisphere,
// by the midpoint rule in (cos theta_l, phi); what a surface under uniform unit radiance reflects.
inline Vec3 glossy_directional_albedo(const GlossyMaterial& m, double mu_v, int n_mu = 1000, int n_phi = 720) {
  const Vec3 v{std::sqrt(std::max(0.0, 1.0 - mu_v * mu_v)), 0.0, mu_v};
  Vec3 sum{};
  const double d_mu = 1.0 / n_mu, d_phi = 2.0 * std::numbers::pi / n_phi;
  for (int i = 0; i < n_mu; ++i) {
    const double mu = (i + 0.5) * d_mu;
    const double s = std::sqrt(1.0 - mu * mu);
    for (int j = 0; j < n_phi; ++j) {
      const double phi = (j + 0.5) * d_phi;
      const Vec3 f = glossy_f_cos(m, v, {s * std::cos(phi), s * std::sin(phi), mu});
      for (int c = 0; c < 3; ++c) sum[c] += f[c];
    }
  }
  for (double& c : sum) c *= d_mu * d_phi;
  return sum;
}

}  // namespace asvgf::reference
