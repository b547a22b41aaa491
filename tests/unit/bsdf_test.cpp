// The glossy BRDF's analytic properties (CPU twin of shaders/common/bsdf.glsl): the GGX
// distribution is normalised, Smith masking preserves the projected area, and the whole model
// reflects at most what arrives (energy conservation) for every parameter combination.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "cpu_oracle/bsdf.hpp"

using namespace asvgf::reference;

namespace {

// Integral over the upper hemisphere of f(mu, phi) by the midpoint rule in (cos theta, phi).
template <typename F>
double hemisphere_integral(F f, int n_mu = 2000, int n_phi = 360) {
  double sum = 0.0;
  const double d_mu = 1.0 / n_mu, d_phi = 2.0 * std::numbers::pi / n_phi;
  for (int i = 0; i < n_mu; ++i) {
    const double mu = (i + 0.5) * d_mu;
    for (int j = 0; j < n_phi; ++j) sum += f(mu, (j + 0.5) * d_phi);
  }
  return sum * d_mu * d_phi;
}

}  // namespace

TEST_CASE("GGX: the projected microfacet area integrates to one, int D(h) cos(theta_h) = 1") {
  for (const double alpha : {0.1, 0.3, 0.6, 1.0}) {
    CAPTURE(alpha);
    const double integral = hemisphere_integral([&](double mu, double) { return ggx_d(mu, alpha) * mu; });
    CHECK(integral == doctest::Approx(1.0).epsilon(1e-3));
  }
}

TEST_CASE("GGX: Smith masking keeps the visible projected area, int G1(v) max(0, v.h) D(h) = cos(theta_v)") {
  for (const double alpha : {0.2, 0.5, 1.0}) {
    for (const double mu_v : {0.2, 0.5, 0.9}) {
      CAPTURE(alpha);
      CAPTURE(mu_v);
      const double sin_v = std::sqrt(1.0 - mu_v * mu_v);
      const double g1 = 1.0 / (1.0 + ggx_lambda(mu_v, alpha));
      const double integral = hemisphere_integral([&](double mu, double phi) {
        const double s = std::sqrt(1.0 - mu * mu);
        const double v_h = sin_v * s * std::cos(phi) + mu_v * mu;
        return g1 * std::max(0.0, v_h) * ggx_d(mu, alpha);
      });
      CHECK(integral == doctest::Approx(mu_v).epsilon(2e-3));
    }
  }
}

// The diffuse lobe's weight 1 - F(n.v) leaves what a smooth dielectric does not reflect; a rough one
// reflects slightly more than F(n.v) (facets turned towards the viewer see a larger Fresnel), so
// the white dielectric gains up to 0.08% (roughness 0.3, n.v 0.7, quadrature 3000 x 1440; glTF's
// own 1 - F(v.h) gains up to 41%). The bound checked is therefore 1 + 1e-3, not 1. The grid
// (800 x 480) resolves lobes of roughness >= 0.3 to 1e-4. The BRDF is linear in metallic and in
// specular (s = 0 is Lambertian, exactly 1), so the ends, the white dielectric with s = 1 and the
// white metal, bound every combination.
TEST_CASE(
    "glossy BRDF: a white surface reflects at most 1.001 of what arrives, for every roughness, metallic and specular") {
  double worst = 0.0;
  for (const double roughness : {0.3, 0.6, 1.0})
    for (const double metallic : {0.0, 1.0})
      for (const double mu_v : {0.1, 0.4, 0.7, 1.0}) {
        const double specular = 1.0;
        const GlossyMaterial m{{1, 1, 1}, roughness, metallic, specular};
        const double albedo = glossy_directional_albedo(m, mu_v, 800, 480)[1];
        worst = std::max(worst, albedo);
        CAPTURE(roughness);
        CAPTURE(metallic);
        CAPTURE(mu_v);
        CHECK(albedo <= 1.0 + 1e-3);
      }
  MESSAGE("largest directional albedo of a white surface: " << worst);
}

TEST_CASE("glossy BRDF: a Lambertian white surface reflects everything, a smooth white metal nearly everything") {
  // specular 0, metallic 0: f cos = cos / pi, albedo 1 exactly.
  CHECK(glossy_directional_albedo({{1, 1, 1}, 0.5, 0.0, 0.0}, 0.6, 400, 240)[0] == doctest::Approx(1.0).epsilon(1e-3));
  // A metal with F0 = 1 loses only what single-scattering GGX misses (light that would scatter
  // between microfacets again, Kulla and Conty 2017): little when smooth, much at alpha 1.
  const double smooth = glossy_directional_albedo({{1, 1, 1}, 0.3, 1.0, 0.0}, 1.0, 2000, 720)[0];
  const double rough = glossy_directional_albedo({{1, 1, 1}, 1.0, 1.0, 0.0}, 1.0)[0];
  MESSAGE("white metal albedo at normal incidence: roughness 0.3 " << smooth << ", roughness 1 " << rough);
  CHECK(smooth > 0.98);
  // At alpha 1, D = 1/pi everywhere and a mirror direction exists only for theta_h < 45 degrees, so
  // E <= int_{theta_h < 45} D cos(theta_h) d(omega_h) = 1/2, and masking takes more (about 0.31).
  CHECK(rough < 0.5);
  CHECK(rough > 0.25);
}
