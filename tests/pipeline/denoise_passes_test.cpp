// Each denoiser pass on the Vulkan device (lavapipe, validation and synchronization validation on:
// any message fails the test) against its double-precision CPU reference, on seeded random inputs
// at sizes that are not multiples of the 8x8 workgroup.
//
// Tolerances follow from the storage formats. Inputs are quantised to their upload formats first,
// so the GPU and the reference start from the same values. Then:
//  - fp16 outputs (RGBA16F): one fp16 ulp of the reference value per store (lavapipe rounds toward
//    zero, others to nearest; both are within one ulp), plus fp32 arithmetic error, bounded by
//    1e-5 x the magnitude of the values summed (exp/pow/division in fp32 vs double);
//  - fp32 outputs: the fp32 arithmetic error alone (1e-5 x magnitude);
//  - RGBA8 display: one 8-bit step (rounding of the store plus fp32 tone-curve error).
#include <doctest/doctest.h>

#include "asvgf/denoiser.hpp"
#include "asvgf/denoiser_graph.hpp"
#include "asvgf/sanitize_counters.hpp"
#include "cpu_oracle/denoise_reference.hpp"
#include "denoiser/passes/atrous.hpp"
#include "denoiser/passes/composite.hpp"
#include "denoiser/passes/convert_inputs.hpp"
#include "denoiser/passes/gradient.hpp"
#include "denoiser/passes/gradient_atrous.hpp"
#include "denoiser/passes/local_mean.hpp"
#include "denoiser/passes/pack_surface.hpp"
#include "denoiser/passes/temporal.hpp"
#include "denoiser/passes/variance.hpp"
#include "pipeline/denoise_chain.hpp"
#include "pipeline/denoise_harness.hpp"
#include "vulkan/validated_device.hpp"

using namespace denoise_test;
using asvgf::graph::Lifetime;
using asvgf::graph::RenderGraph;
using F = hal::Format;
namespace ref = asvgf::reference;
namespace passes = asvgf::passes;

namespace {

constexpr int kSizes[][2] = {{17, 13}, {32, 32}, {9, 5}};

auto fp16_tolerance(double magnitude) {
  return [magnitude](double want) { return fp16_ulp(want) + 1e-5 * magnitude; };
}
// fp16_tolerance for the colour of RGB9E5 `words` (common/filter_texel.glsl): the colour channels
// also round to RGB9E5, by at most half the stored word's quantum (rgb9e5_canonical checks that the
// exponent is the smallest that holds the largest channel, so that the quantum is not too coarse).
auto rgb9e5_tolerance(const ImageD& words, double magnitude) {
  return [&words, magnitude](int x, int y, int c, double w) {
    const double half_quantum = 0.5 * rgb9e5_quantum(static_cast<std::uint32_t>(words.at(x, y, 0)));
    return (c < 3 ? half_quantum : 0.0) + fp16_ulp(w) + 1e-5 * magnitude;
  };
}
// Words whose exponent is above 0 with every mantissa below 256: one exponent step coarser than the
// largest channel needs.
int rgb9e5_not_canonical(const ImageD& words) {
  int count = 0;
  for (int y = 0; y < words.height; ++y)
    for (int x = 0; x < words.width; ++x) {
      const auto word = static_cast<std::uint32_t>(words.at(x, y, 0));
      const std::uint32_t largest = std::max({word & 511u, (word >> 9) & 511u, (word >> 18) & 511u});
      count += (word >> 27) > 0 && largest < 256;
    }
  return count;
}
// A colour history (RGB9E5 words, as a spatial chain keeps it) holds `color` (an RGBA16F result
// of the same fp32 values): within rgb9e5_tolerance, with canonical exponents.
void check_history_words(const ImageD& words, const ImageD& color, const std::string& what) {
  DENOISE_CHECK_CLOSE(compare(rgb9e5_values(words), color, 3, rgb9e5_tolerance(words, 0)), what);
  CHECK_MESSAGE(rgb9e5_not_canonical(words) == 0, what);
}
auto fp32_tolerance(double magnitude) {
  return [magnitude](double) { return 1e-5 * magnitude; };
}

}  // namespace

TEST_CASE(
    "denoise passes: convert_inputs demodulates radiance where the albedo allows and converts motion conventions") {
  ValidatedDevice device;
  passes::PipelineCache pipelines(*device);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // (radiance?, motion scale): ours, Cycles (y up), NRD-style UV at 17x13, current-minus-previous NDC.
  const struct {
    bool radiance;
    asvgf::MotionConvention convention;
  } cases[] = {{true, asvgf::MotionConvention::ours()},
               {true, asvgf::MotionConvention::cycles()},
               {false, asvgf::MotionConvention::nrd()},
               {true, {false, asvgf::MotionUnits::Ndc, false}}};
  for (const auto& size : kSizes)
    for (const auto& k : cases) {
      const int w = size[0], h = size[1];
      CAPTURE(w);
      CAPTURE(h);
      CAPTURE(k.radiance);
      Random r(41u + static_cast<std::uint32_t>(w));
      ImageD color(w, h, 4), albedo(w, h, 4), motion(w, h, 4);
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
          for (int c = 0; c < 4; ++c) {
            color.at(x, y, c) = r.uniform(0, 4);
            albedo.at(x, y, c) = r.chance(0.1) ? r.uniform(0, 2e-3) : r.uniform(0.01, 3);  // emitters above 1
            motion.at(x, y, c) = r.uniform(-20, 20);
          }
      albedo.at(0, 0, 0) = nan;   // no albedo: the radiance passes through
      albedo.at(1, 0, 1) = -0.5;  // likewise
      albedo.at(2, 0, 2) = 0.0;
      const auto scale =
          asvgf::motion_scale(k.convention, static_cast<std::uint32_t>(w), static_cast<std::uint32_t>(h));
      GraphHarness harness(*device);
      RenderGraph g;
      const auto cin = harness.input(g, "color", color, F::RGBA32F);
      const auto ain = harness.input(g, "albedo", albedo, F::RGBA32F);
      const auto min = harness.input(g, "motion", motion, F::RGBA32F);
      const auto uw = static_cast<std::uint32_t>(w), uh = static_cast<std::uint32_t>(h);
      const auto illum = g.add_image("illumination", uw, uh, F::RGBA32F);
      const auto modulation = g.add_image("modulation", uw, uh, F::R32Uint);
      const auto mout = g.add_image("motion_out", uw, uh, F::RGBA32F);
      passes::add_convert_inputs(g, pipelines, {cin, ain, min, illum, modulation, mout},
                                 {k.radiance, scale[0], scale[1]});
      ImageD got_i, got_m_words, got_v;
      harness.readback(g, illum, &got_i);
      harness.readback(g, modulation, &got_m_words);
      harness.readback(g, mout, &got_v);
      harness.run(g);
      const auto want = ref::convert_inputs(quantize(color, F::RGBA32F), quantize(albedo, F::RGBA32F),
                                            quantize(motion, F::RGBA32F), k.radiance, scale[0], scale[1]);
      if (k.radiance) {
        // A division: fp32 error relative to the quotient, which reaches 4 / 1e-3.
        DENOISE_CHECK_CLOSE(compare(got_i, want.illumination, 3, [](double v) { return 1e-6 * std::abs(v) + 1e-7; }),
                            "illumination");
        // RGB9E5 words, the radiance divided by what they hold: the same words as the twin's.
        const ImageD got_m = rgb9e5_values(got_m_words);
        DENOISE_CHECK_CLOSE(compare(got_m, want.modulation, 3, [](double) { return 0.0; }), "modulation");
        CHECK(got_m.at(0, 0, 0) == 1.0);
        CHECK(got_m.at(1, 0, 1) == 1.0);
        CHECK(got_m.at(2, 0, 2) == 1.0);
      } else {
        DENOISE_CHECK_CLOSE(compare(got_i, want.illumination, 3, fp32_tolerance(0)), "illumination");
      }
      DENOISE_CHECK_CLOSE(compare(got_v, want.motion, 2, [](double v) { return 1e-6 * std::abs(v); }), "motion");
    }
}

TEST_CASE("denoise passes: pack_surface matches the CPU reference, bad depths and normals become background") {
  ValidatedDevice device;
  passes::PipelineCache pipelines(*device);
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (const auto& size : kSizes)
    for (const bool given : {false, true}) {
      const int w = size[0], h = size[1];
      CAPTURE(w);
      CAPTURE(h);
      CAPTURE(given);
      Random r(23u + static_cast<std::uint32_t>(w));
      ImageD depth(w, h, 2), normal(w, h, 3);
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          const double step = (x / 4 + y / 3) % 3 == 0 ? 2.0 : 0.0;  // silhouettes
          depth.at(x, y, 0) = r.chance(0.07) ? 0.0 : 2.0 + 0.05 * x + 0.02 * y + step;
          depth.at(x, y, 1) = r.uniform(0, 0.1);
          for (int c = 0; c < 3; ++c) normal.at(x, y, c) = r.uniform(-2, 2);  // any length
        }
      // Each way an input can be unusable, and a given gradient that is not (the estimate is used).
      depth.at(0, 0, 0) = nan;
      depth.at(1, 0, 0) = -3.0;
      depth.at(2, 0, 0) = inf;
      normal.at(3, 0, 1) = nan;
      normal.at(4, 0, 0) = normal.at(4, 0, 1) = normal.at(4, 0, 2) = 0.0;
      normal.at(0, 1, 2) = inf;
      depth.at(1, 1, 0) = 5.0, depth.at(1, 1, 1) = nan;
      depth.at(2, 1, 0) = 5.0, depth.at(2, 1, 1) = -1.0;
      GraphHarness harness(*device);
      RenderGraph g;
      const auto d = harness.input(g, "depth", depth, F::RG32F);
      const auto n = harness.input(g, "normal", normal, F::RGBA32F);
      const auto out =
          g.add_image("depth_normal", static_cast<std::uint32_t>(w), static_cast<std::uint32_t>(h), F::RGBA16Uint);
      passes::add_pack_surface(g, pipelines, {d, n, out}, given);
      ImageD texels;
      harness.readback(g, out, &texels);
      harness.run(g);
      const ImageD got = depth_normal_values(texels);
      const ImageD want = ref::pack_surface(quantize(depth, F::RG32F), quantize(normal, F::RGBA32F), given);
      // The depth is passed through and rounded by integer arithmetic on its bits: exact. The gradient
      // (a difference of two fp32 depths) and the octahedral coordinates (fp32 arithmetic) may land
      // on the other side of a rounding: one step of their encodings (bfloat16, snorm12).
      DENOISE_CHECK_CLOSE(compare(got, want, 4,
                                  [](double v, int c) {
                                    return c == 0 ? 1e-30 : c == 1 ? std::ldexp(std::abs(v), -8) + 1e-30 : 1.0 / 2047;
                                  }),
                          "pack_surface");
      int background = 0;
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          const bool got_bg =
              got.at(x, y, 0) == 0 && got.at(x, y, 1) == 0 && got.at(x, y, 2) == 0 && got.at(x, y, 3) == 0;
          CHECK_MESSAGE(got_bg == (want.at(x, y, 0) == 0), "background at " << x << "," << y);
          background += got_bg;
        }
      for (int x = 0; x < 5; ++x) CHECK(got.at(x, 0, 0) == 0.0);
      CHECK(got.at(0, 1, 0) == 0.0);
      CHECK(got.at(1, 1, 0) == 5.0f);
      CHECK(std::isfinite(got.at(1, 1, 1)));
      CHECK(got.at(2, 1, 1) >= 0.0);
      CHECK(background >= 6);
    }
}

// Both ways a renderer hands over the re-shaded sample: as its pixel of the illumination, or as the
// gradient sample's z (current_given), where the pixel's own sample must not be read.
TEST_CASE(
    "denoise passes: gradient pass matches the CPU reference, l_cur from the pixel or from the sample, and the first "
    "gradient a-trous iteration from the samples equals the two passes") {
  ValidatedDevice device;
  passes::PipelineCache pipelines(*device);
  for (const bool given : {false, true})
    for (const auto& size : kSizes) {
      const int w = size[0], h = size[1], gw = (w + 2) / 3, gh = (h + 2) / 3;
      CAPTURE(given);
      CAPTURE(w);
      CAPTURE(h);
      Random r(11u + static_cast<std::uint32_t>(w));
      ImageD illumination = random_color(r, w, h, 0, 4, 0);
      illumination.at(1, 1, 0) = std::numeric_limits<double>::quiet_NaN();  // a dropped sample
      illumination.at(2, 0, 1) = std::numeric_limits<double>::infinity();
      illumination.at(0, 1, 2) = 1e6;  // clamped to fp16 max
      ImageD prev(gw, gh, given ? 3 : 2);
      for (int y = 0; y < gh; ++y)
        for (int x = 0; x < gw; ++x) {
          prev.at(x, y, 0) = static_cast<float>(r.uniform(0, 4));
          prev.at(x, y, 1) = r.chance(0.2) ? -1.0 : static_cast<double>(static_cast<int>(r.uniform(0, 9)));
          if (given) prev.at(x, y, 2) = r.chance(0.1) ? -1.0 : static_cast<float>(r.uniform(0, 4));
        }
      prev.at(0, 0, 1) = 4;  // the pixel with the NaN
      if (given && gw > 1) {
        prev.at(1, 0, 1) = 0;  // z: not finite, and above the fp16 maximum
        prev.at(1, 0, 2) = std::numeric_limits<double>::quiet_NaN();
        prev.at(0, 0, 2) = 1e6;
      }
      GraphHarness harness(*device);
      RenderGraph g;
      const auto in = harness.input(g, "illumination", illumination, F::RGBA32F);
      const auto gp = harness.input(g, "gradient_prev", prev, given ? F::RGBA32F : F::RG32F);
      const auto out =
          g.add_image("gradient", static_cast<std::uint32_t>(gw), static_cast<std::uint32_t>(gh), F::RGBA16F);
      passes::add_gradient(g, pipelines, {in, gp, out, false, given});
      ImageD got;
      harness.readback(g, out, &got);
      // With l_cur given, the first gradient a-trous iteration computes the gradient from the samples
      // itself (the denoiser then runs no gradient pass): to the bit what this pass and a plain
      // iteration give, with and without writing the strata guide.
      ImageD got_two_passes, got_from_samples, got_from_samples_guide;
      if (given) {
        const auto ugw = static_cast<std::uint32_t>(gw), ugh = static_cast<std::uint32_t>(gh);
        const auto dn =
            harness.input(g, "depth_normal", depth_normal_texels(random_depth_normal(r, w, h)), F::RGBA16Uint);
        const auto two_passes = g.add_image("gradient.1", ugw, ugh, F::RGBA16F);
        const auto from_samples = g.add_image("gradient.1.samples", ugw, ugh, F::RGBA16F);
        const auto from_samples_guide = g.add_image("gradient.1.samples_guide", ugw, ugh, F::RGBA16F);
        const auto guide = g.add_image("gradient_guide", ugw, ugh, F::RGBA16Uint);
        const asvgf::DenoiseSettings settings;
        passes::add_gradient_atrous(g, pipelines, {out, dn, two_passes}, 0, settings);
        passes::add_gradient_atrous(g, pipelines, {gp, dn, from_samples, std::nullopt, std::nullopt, true}, 0,
                                    settings);
        passes::add_gradient_atrous(g, pipelines, {gp, dn, from_samples_guide, guide, std::nullopt, true}, 0, settings);
        harness.readback(g, two_passes, &got_two_passes);
        harness.readback(g, from_samples, &got_from_samples);
        harness.readback(g, from_samples_guide, &got_from_samples_guide);
      }
      harness.run(g);
      if (given) {
        int differ = 0, differ_guide = 0;
        for (std::size_t i = 0; i < got_two_passes.data.size(); ++i) {
          differ += got_from_samples.data[i] != got_two_passes.data[i];
          differ_guide += got_from_samples_guide.data[i] != got_two_passes.data[i];
        }
        CHECK(differ == 0);
        CHECK(differ_guide == 0);
      }
      const ImageD want =
          ref::gradient(quantize(illumination, F::RGBA32F), quantize(prev, given ? F::RGBA32F : F::RG32F), given);
      DENOISE_CHECK_CLOSE(compare(got, want, 2, fp16_tolerance(4)), "gradient");
      if (given) {
        // The pixel's NaN is not read: l_cur is z, clamped to the fp16 maximum.
        CHECK(got.at(0, 0, 1) == 65504.0);
        if (gw > 1) CHECK(got.at(1, 0, 1) == 0.0);  // a missing l_cur: nothing
      } else {
        CHECK(got.at(0, 0, 0) == 0.0);
        CHECK(got.at(0, 0, 1) == 0.0);
      }
    }
}

// Each iteration three ways: guided by depth_normal (plain), also writing the strata guide (the
// first of several), and guided by that strata guide (the later ones).
TEST_CASE(
    "denoise passes: gradient_atrous pass matches the CPU reference at steps 1, 2 and 4, guided by depth_normal or by "
    "the strata guide") {
  ValidatedDevice device;
  passes::PipelineCache pipelines(*device);
  asvgf::DenoiseSettings settings;
  for (const auto& size : kSizes) {
    const int w = size[0], h = size[1], gw = (w + 2) / 3, gh = (h + 2) / 3;
    Random r(23u + static_cast<std::uint32_t>(w));
    const ImageD dn = random_depth_normal(r, w, h);
    ImageD grad(gw, gh, 4);
    for (int y = 0; y < gh; ++y)
      for (int x = 0; x < gw; ++x)
        if (!r.chance(0.3)) grad.at(x, y, 0) = r.uniform(-2, 2), grad.at(x, y, 1) = r.uniform(0, 3);
    const auto ugw = static_cast<std::uint32_t>(gw), ugh = static_cast<std::uint32_t>(gh);
    for (int iteration = 0; iteration < 3; ++iteration) {
      CAPTURE(w);
      CAPTURE(iteration);
      GraphHarness harness(*device);
      RenderGraph g;
      const auto gin = harness.input(g, "gradient_in", grad, F::RGBA16F);
      const auto dni = harness.input(g, "depth_normal", depth_normal_texels(dn), F::RGBA16Uint);
      const auto plain = g.add_image("gradient_out.plain", ugw, ugh, F::RGBA16F);
      const auto first = g.add_image("gradient_out.first", ugw, ugh, F::RGBA16F);
      const auto rest = g.add_image("gradient_out.rest", ugw, ugh, F::RGBA16F);
      const auto guide = g.add_image("gradient_guide", ugw, ugh, F::RGBA16Uint);
      passes::add_gradient_atrous(g, pipelines, {gin, dni, plain}, iteration, settings);
      passes::add_gradient_atrous(g, pipelines, {gin, dni, first, guide}, iteration, settings);
      passes::add_gradient_atrous(g, pipelines, {gin, dni, rest, std::nullopt, guide}, iteration, settings);
      ImageD got_plain, got_first, got_rest, got_guide;
      harness.readback(g, plain, &got_plain);
      harness.readback(g, first, &got_first);
      harness.readback(g, rest, &got_rest);
      harness.readback(g, guide, &got_guide);
      harness.run(g);
      const ImageD want = ref::gradient_atrous(quantize(grad, F::RGBA16F), quantize(dn, F::RGBA32F),
                                               {1 << iteration, settings.sigma_z, settings.sigma_n});
      DENOISE_CHECK_CLOSE(compare(got_plain, want, 2, fp16_tolerance(3)), "gradient_atrous");
      DENOISE_CHECK_CLOSE(compare(got_first, want, 2, fp16_tolerance(3)), "gradient_atrous writing the strata guide");
      DENOISE_CHECK_CLOSE(compare(got_rest, want, 2, fp16_tolerance(3)), "gradient_atrous on the strata guide");
      // The strata guide is depth_normal's texel at each stratum's centre pixel, to the bit.
      const ImageD dn_q = depth_normal_texels(dn);
      int guide_errors = 0;
      for (int y = 0; y < gh; ++y)
        for (int x = 0; x < gw; ++x)
          for (int c = 0; c < 4; ++c)
            guide_errors += got_guide.at(x, y, c) != dn_q.at(std::min(3 * x + 1, w - 1), std::min(3 * y + 1, h - 1), c);
      CHECK(guide_errors == 0);
    }
  }
  RenderGraph g;
  const auto gin = g.add_image("gradient_in", 3, 3, F::RGBA16F), dn = g.add_image("depth_normal", 8, 8, F::RGBA16Uint);
  const auto out = g.add_image("gradient_out", 3, 3, F::RGBA16F), guide = g.add_image("guide", 3, 3, F::RGBA16Uint);
  CHECK_THROWS_AS(passes::add_gradient_atrous(g, pipelines, {gin, dn, out, guide, guide}, 1, settings),
                  std::invalid_argument);
  CHECK_THROWS_AS(
      passes::add_gradient_atrous(g, pipelines, {gin, dn, out, g.add_image("wide", 4, 3, F::RGBA16Uint)}, 0, settings),
      std::invalid_argument);
  // The samples' gradients are computed into a tile with step 1's apron.
  CHECK_THROWS_AS(
      passes::add_gradient_atrous(g, pipelines, {gin, dn, out, std::nullopt, std::nullopt, true}, 1, settings),
      std::invalid_argument);
}

namespace {

struct TemporalCase {
  ImageD illumination, motion, dn, prev_dn, prev_color, prev_moments, gradient;
};

TemporalCase random_temporal_case(std::uint32_t seed, int w, int h) {
  Random r(seed);
  TemporalCase c;
  c.illumination = random_color(r, w, h, 0, 4, 0);
  for (int k = 0; k < w * h / 25 + 2; ++k) {  // ~4% dropped samples
    const int x = static_cast<int>(r.uniform(0, w)), y = static_cast<int>(r.uniform(0, h));
    c.illumination.at(x, y, static_cast<int>(r.uniform(0, 3))) =
        r.chance(0.5) ? std::numeric_limits<double>::quiet_NaN()
                      : (r.chance(0.5) ? 1.0 : -1.0) * std::numeric_limits<double>::infinity();
  }
  c.motion = ImageD(w, h, 2);
  for (auto& v : c.motion.data) v = static_cast<float>(r.uniform(-1.5, 1.5));
  c.motion.at(0, 0, 0) = -40;  // off screen
  c.dn = random_depth_normal(r, w, h);
  c.prev_dn = c.dn;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (r.chance(0.1)) c.prev_dn.at(x, y, 0) = c.dn.at(x, y, 0) * 1.3;  // disocclusion
  c.prev_dn = depth_normal_as_stored(c.prev_dn);
  c.prev_color = random_color(r, w, h, 0, 4, 1);
  c.prev_moments = ImageD(w, h, 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double m1 = r.uniform(0, 4);
      c.prev_moments.at(x, y, 0) = static_cast<float>(m1);
      c.prev_moments.at(x, y, 1) = static_cast<float>(std::sqrt(r.uniform(0, 2)));
      c.prev_moments.at(x, y, 2) = r.chance(0.1) ? 0.0 : static_cast<double>(static_cast<int>(r.uniform(1, 40)));
    }
  c.gradient = ImageD((w + 2) / 3, (h + 2) / 3, 4);
  for (int y = 0; y < c.gradient.height; ++y)
    for (int x = 0; x < c.gradient.width; ++x)
      if (!r.chance(0.2)) c.gradient.at(x, y, 0) = r.uniform(-2, 2), c.gradient.at(x, y, 1) = r.uniform(0, 3);
  return c;
}

}  // namespace

TEST_CASE(
    "denoise passes: gradient_reprojected matches the CPU reference (luminance sums per stratum, history and NaN "
    "handled)") {
  ValidatedDevice device;
  passes::PipelineCache pipelines(*device);
  for (const auto& size : kSizes) {
    const int w = size[0], h = size[1], gw = (w + 2) / 3, gh = (h + 2) / 3;
    CAPTURE(w);
    const auto uw = static_cast<std::uint32_t>(w), uh = static_cast<std::uint32_t>(h);
    const TemporalCase c = random_temporal_case(53u + static_cast<std::uint32_t>(w), w, h);
    Random r(71u + static_cast<std::uint32_t>(w));
    ImageD prev_luminance(w, h, 1);
    for (auto& v : prev_luminance.data) v = static_cast<float>(r.uniform(0, 4));
    GraphHarness harness(*device);
    ImageD gradient, luminance;
    for (int frame = 0; frame < 2; ++frame) {
      RenderGraph g;
      const auto dn = g.add_image("depth_normal", uw, uh, F::RGBA16Uint, Lifetime::Persistent);
      const auto lum = g.add_image("noisy_luminance", uw, uh, F::R32F, Lifetime::Persistent);
      if (frame == 0) {
        harness.fill(g, dn, depth_normal_texels(c.prev_dn));
        harness.fill(g, lum, prev_luminance);
      } else {
        harness.fill(g, dn, depth_normal_texels(c.dn));
        const auto illumination = harness.input(g, "illumination", c.illumination, F::RGBA32F);
        const auto motion = harness.input(g, "motion", c.motion, F::RG32F);
        const auto out =
            g.add_image("gradient", static_cast<std::uint32_t>(gw), static_cast<std::uint32_t>(gh), F::RGBA16F);
        passes::add_gradient_reprojected(g, pipelines, {illumination, motion, dn, lum, out});
        harness.readback(g, out, &gradient);
        harness.readback(g, lum, &luminance);
      }
      harness.run(g);
    }
    const ImageD illumination = quantize(c.illumination, F::RGBA32F), motion = quantize(c.motion, F::RG32F);
    const ImageD dn = quantize(c.dn, F::RGBA32F), prev_dn = quantize(c.prev_dn, F::RGBA32F);
    const ImageD prev_lum = quantize(prev_luminance, F::R32F);
    const auto want = ref::gradient_reprojected({&illumination, &motion, &dn, &prev_dn, &prev_lum, true});
    // Sums of up to 9 luminances in [0, 4]: fp16 store of values up to 36.
    DENOISE_CHECK_CLOSE(compare(gradient, want.gradient, 2, fp16_tolerance(36)), "gradient_reprojected");
    DENOISE_CHECK_CLOSE(compare(luminance, want.luminance, 1, fp32_tolerance(4)), "noisy luminance");
    // The case exercises the sums: strata with matched pixels (Delta > 0) whose luminance changed.
    int changed = 0;
    for (int y = 0; y < gh; ++y)
      for (int x = 0; x < gw; ++x) changed += want.gradient.at(x, y, 1) > 0 && want.gradient.at(x, y, 0) != 0;
    CHECK(changed > 0);
  }
}

TEST_CASE(
    "denoise passes: temporal pass matches the CPU reference (constant and adaptive alpha, dropped and clamped samples "
    "counted, the colour history and result in RGBA16F and as RGB9E5 words)") {
  ValidatedDevice device;
  passes::PipelineCache pipelines(*device);
  for (const auto& [adaptive, words] : {std::pair{false, false}, {true, false}, {false, true}, {true, true}}) {
    const F color_format = words ? F::R32Uint : F::RGBA16F;  // the EMA's, a spatial chain's
    for (const auto& size : kSizes) {
      const int w = size[0], h = size[1];
      CAPTURE(adaptive);
      CAPTURE(words);
      CAPTURE(w);
      const auto uw = static_cast<std::uint32_t>(w), uh = static_cast<std::uint32_t>(h);
      TemporalCase c = random_temporal_case(37u + static_cast<std::uint32_t>(w), w, h);
      // Clamped and counted at and above the fp16 maximum (a half-float input's saturated samples), not below.
      c.illumination.at(w - 1, h - 1, 0) = 65504;
      c.illumination.at(w - 2, h - 1, 1) = 1e6;
      c.illumination.at(w - 3, h - 1, 2) = 65503.98828125;  // the largest float below
      asvgf::DenoiseSettings settings;
      if (w == 32) settings.antilag = 3.0f;  // a stronger response to the gradient, in one size
      passes::SanitizeCounters counters(*device);
      GraphHarness harness(*device);
      ImageD integrated, moments;
      // Frame 0 writes last frame's state into the persistent resources; frame 1 runs the pass.
      for (int frame = 0; frame < 2; ++frame) {
        RenderGraph g;
        const auto dn = g.add_image("depth_normal", uw, uh, F::RGBA16Uint, Lifetime::Persistent);
        const auto color = g.add_image("color_history", uw, uh, color_format, Lifetime::Persistent);
        const auto mom = g.add_image("moments", uw, uh, F::R32Uint, Lifetime::Persistent);
        if (frame == 0) {
          harness.fill(g, dn, depth_normal_texels(c.prev_dn));
          harness.fill(g, color, words ? rgb9e5_words(c.prev_color) : c.prev_color);
          harness.fill(g, mom, moments_words(c.prev_moments));
        } else {
          harness.fill(g, dn, depth_normal_texels(c.dn));
          passes::TemporalResources res;
          res.illumination = harness.input(g, "illumination", c.illumination, F::RGBA32F);
          res.motion = harness.input(g, "motion", c.motion, F::RG32F);
          res.depth_normal = dn;
          res.color_history = color;
          res.moments = mom;
          res.integrated = g.add_image("integrated", uw, uh, color_format);
          res.counters = counters.import(g);
          if (adaptive) res.gradient = harness.input(g, "gradient", c.gradient, F::RGBA16F);
          passes::add_temporal(g, pipelines, res, settings);
          harness.readback(g, res.integrated, &integrated);
          harness.readback(g, mom, &moments);
        }
        harness.run(g);
      }
      const ImageD illumination = quantize(c.illumination, F::RGBA32F), motion = quantize(c.motion, F::RG32F);
      const ImageD dn = quantize(c.dn, F::RGBA32F), prev_dn = quantize(c.prev_dn, F::RGBA32F);
      const ImageD prev_color = words ? rgb9e5_values(rgb9e5_words(c.prev_color)) : quantize(c.prev_color, F::RGBA16F);
      const ImageD prev_moments = moments_values(moments_words(c.prev_moments));
      const ImageD gradient = quantize(c.gradient, F::RGBA16F);
      ref::TemporalInputs in{
          &illumination, &motion, &dn, &prev_dn, &prev_color, &prev_moments, adaptive ? &gradient : nullptr};
      const auto want =
          ref::temporal(in, {settings.alpha, settings.moments_alpha, settings.history_cap, true, settings.antilag});
      if (words) {
        DENOISE_CHECK_CLOSE(compare(rgb9e5_values(integrated), want.integrated, 3, rgb9e5_tolerance(integrated, 4)),
                            "temporal colour, RGB9E5 words");
        CHECK(rgb9e5_not_canonical(integrated) == 0);
      } else {
        DENOISE_CHECK_CLOSE(compare(integrated, want.integrated, 3, fp16_tolerance(4)), "temporal colour");
        DENOISE_CHECK_CLOSE(compare(integrated, want.integrated, 4, fp16_tolerance(20)), "temporal variance");
      }
      DENOISE_CHECK_CLOSE(compare_moments(moments_values(moments), want.moments, 40, 20),
                          "temporal moments and length");
      const auto counts = counters.read();
      CHECK(counts.nan_samples == want.nan_samples);
      CHECK(counts.inf_samples == want.inf_samples);
      CHECK(want.nan_samples + want.inf_samples > 0);
      CHECK(counts.clamped_samples == want.clamped_samples);
      CHECK(want.clamped_samples >= 2);
      // The reference exercises both outcomes of reprojection.
      int reset = 0, kept = 0;
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) (want.moments.at(x, y, 2) <= 1.0 ? reset : kept)++;
      CHECK(reset > 0);
      CHECK(kept > 0);
    }
  }
}

namespace {

// The variance pass on these inputs (integrated as RGB9E5 words, as a spatial chain keeps it,
// moments as pack_moments's words, albedo as RGBA16F, depth_normal as its texels), read back.
ImageD run_variance(hal::Device& device, passes::PipelineCache& pipelines, const ImageD& integrated,
                    const ImageD& moments, const ImageD& dn, const ImageD& albedo,
                    const asvgf::DenoiseSettings& settings) {
  GraphHarness harness(device);
  RenderGraph g;
  const auto out = g.add_image("color_variance", static_cast<std::uint32_t>(integrated.width),
                               static_cast<std::uint32_t>(integrated.height), F::RGBA16F);
  passes::add_variance(g, pipelines,
                       {harness.input(g, "integrated", rgb9e5_words(integrated), F::R32Uint),
                        harness.input(g, "moments", moments_words(moments), F::R32Uint),
                        harness.input(g, "depth_normal", depth_normal_texels(dn), F::RGBA16Uint), out,
                        harness.input(g, "albedo", albedo, F::RGBA16F)},
                       settings);
  ImageD got;
  harness.readback(g, out, &got);
  harness.run(g);
  return got;
}

}  // namespace

TEST_CASE("denoise passes: variance pass matches the CPU reference (temporal and spatial estimates)") {
  ValidatedDevice device;
  passes::PipelineCache pipelines(*device);
  asvgf::DenoiseSettings settings;
  for (const auto& size : kSizes) {
    const int w = size[0], h = size[1];
    CAPTURE(w);
    Random r(51u + static_cast<std::uint32_t>(w));
    const ImageD dn = random_depth_normal(r, w, h);
    const ImageD integrated = random_color(r, w, h, 0, 4, 2);
    const ImageD moments = random_moments(r, w, h);
    const ImageD albedo = random_color(r, w, h, 0.05, 1, 1);  // textured: a different albedo at every pixel
    const ImageD got = run_variance(*device, pipelines, integrated, moments, dn, albedo, settings);
    const ImageD want = ref::variance(
        rgb9e5_values(rgb9e5_words(integrated)), moments_values(moments_words(moments)), quantize(dn, F::RGBA32F),
        quantize(albedo, F::RGBA16F),
        {settings.sigma_z, settings.sigma_n,
         asvgf::luminance_sigma(settings, std::uint32_t(dn.width), std::uint32_t(dn.height)), settings.min_history});
    DENOISE_CHECK_CLOSE(compare(got, want, 4, fp16_tolerance(80)), "variance");
  }
}

// Dividing an untextured surface's light by its albedo a, and multiplying the result back, must
// change nothing: the demodulated estimate is the radiance's colour / a and variance / a^2. With
// a = 1/4 every scaling is exact in fp16 and fp32, so the two runs agree to the bit. The spatial
// estimate's luminance weight, which has no variance to scale by, broke this when it compared the
// demodulated signal (docs/quality.md: demodulation where it should be neutral).
TEST_CASE("denoise passes: the variance estimate of demodulated light is the radiance's, scaled (grey albedo)") {
  ValidatedDevice device;
  passes::PipelineCache pipelines(*device);
  asvgf::DenoiseSettings settings;
  const int w = 29, h = 23;
  Random r(53u);
  const ImageD dn = random_depth_normal(r, w, h);
  const ImageD radiance = quantize(random_color(r, w, h, 0, 4, 2), F::RGBA16F);
  const ImageD moments = random_moments(r, w, h);
  constexpr double kAlbedo = 0.25;
  const auto run = [&](double albedo_value) {
    ImageD integrated = radiance, m = moments, albedo(w, h, 4);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        for (int c = 0; c < 4; ++c) {
          integrated.at(x, y, c) /= c < 3 ? albedo_value : albedo_value * albedo_value;
          albedo.at(x, y, c) = albedo_value;
        }
        m.at(x, y, 0) /= albedo_value;
        m.at(x, y, 1) /= albedo_value;  // the standard deviation
      }
    return run_variance(*device, pipelines, integrated, m, dn, albedo, settings);
  };
  const ImageD of_radiance = run(1.0), of_demodulated = run(kAlbedo);
  int spatial = 0, differing = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double n = moments.at(x, y, 2);
      spatial += dn.at(x, y, 0) > 0 && n > 0 && n < settings.min_history;
      for (int c = 0; c < 4; ++c) {
        const double scale = c < 3 ? kAlbedo : kAlbedo * kAlbedo;
        differing += of_demodulated.at(x, y, c) * scale != of_radiance.at(x, y, c);
      }
    }
  CHECK(spatial > w * h / 4);  // the spatial estimate, which the property is about, runs
  CHECK(differing == 0);
}

namespace {

// An 8x8 graph's denoiser inputs for the refusal checks, the albedo in `albedo_format`.
passes::GraphDenoiserInputs refusal_inputs(RenderGraph& g, F albedo_format) {
  passes::GraphDenoiserInputs in;
  in.illumination = g.add_image("illumination", 8, 8, F::RGBA32F);
  in.motion = g.add_image("motion", 8, 8, F::RGBA32F);
  in.depth_normal = g.add_image("depth_normal", 8, 8, F::RGBA16Uint, Lifetime::Persistent);
  in.albedo = g.add_image("albedo", 8, 8, albedo_format);
  in.hdr = g.add_image("hdr", 8, 8, F::RGBA32F);
  in.display = g.add_image("display", 8, 8, F::RGBA8Unorm);
  return in;
}

}  // namespace

// The specular chain's variance estimate and composite read the specular albedo: a graph that
// names a specular signal without it is refused where it is declared, not at a null resource.
TEST_CASE("denoise passes: add_denoiser refuses a specular signal without its specular_albedo") {
  ValidatedDevice device;
  passes::PipelineCache pipelines(*device);
  RenderGraph g;
  passes::GraphDenoiserInputs in = refusal_inputs(g, F::RGBA16F);
  in.specular = g.add_image("specular", 8, 8, F::RGBA32F);
  CHECK_THROWS_AS(passes::add_denoiser(g, pipelines, in, asvgf::DenoiseSettings{}, asvgf::DenoiseMethod::Svgf),
                  std::invalid_argument);
}

// The albedo as RGB9E5 words and the motion as two halves a word (R32Uint, 4 bytes a pixel each:
// our G-buffer's, shaders/common/albedo.glsl and motion.glsl) are the float images of the values
// they hold: every pass that reads them (the temporal pass, the reprojected gradient, the variance
// pass, the first iteration's estimate, the composite pass or the last iteration that composites)
// gives the frames the float images give, to the bit, over the short-history frames where the
// estimate reads the albedo.
TEST_CASE("denoise passes: the albedo and motion words denoise as the float images of the values they hold") {
  ValidatedDevice device;
  const int w = 24, h = 20;
  Random r(17);
  denoise_test::FrameInput in{random_color(r, w, h, 0.0, 3.0, 0.0), random_depth_normal(r, w, h), ImageD(w, h, 2),
                              ImageD(w, h, 4), std::nullopt};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      for (int c = 0; c < 3; ++c)  // dark channels beside bright ones, where the words round most
        in.albedo.at(x, y, c) = r.chance(0.3) ? r.uniform(0.0, 0.05) : r.uniform(0.05, 1.0);
      for (int c = 0; c < 2; ++c)  // sub-pixel motion, as halves hold it
        in.motion.at(x, y, c) = half_to_float(float_to_half(static_cast<float>(r.uniform(-1.5, 1.5))));
    }
  in.albedo = rgb9e5_values(rgb9e5_words(in.albedo));
  REQUIRE(in.albedo.data != ImageD(w, h, 4).data);
  struct Case {
    int local_mean;  // -1: the composite pass applies the correction; 0: the last iteration composites
    asvgf::GradientSource gradient;
  };
  for (const Case k : {Case{-1, asvgf::GradientSource::Reshaded}, Case{0, asvgf::GradientSource::Reprojected}}) {
    CAPTURE(k.local_mean);
    asvgf::DenoiseSettings s;
    s.local_mean = k.local_mean;
    s.gradient_source = k.gradient;
    denoise_test::DenoiserChain floats(*device, s, {F::RGBA32F, F::RG32F, true}),
        words(*device, s, {F::R32Uint, F::R32Uint, true});
    for (int frame = 0; frame < 6; ++frame) {
      CAPTURE(frame);
      denoise_test::FrameInput f = in;
      Random noise(100u + static_cast<std::uint32_t>(frame));
      for (double& v : f.illumination.data) v *= noise.uniform(0.5, 1.5);
      const auto a = floats.run(f), b = words.run(f);
      CHECK(a.hdr.data == b.hdr.data);
      CHECK(a.display.data == b.display.data);
      CHECK(a.variance.data == b.variance.data);
    }
  }
  // Any other integer format is refused where the pass that reads it is declared, naming it.
  passes::PipelineCache pipelines(*device);
  RenderGraph g;
  const passes::GraphDenoiserInputs bad = refusal_inputs(g, F::RGBA16Uint);
  CHECK_THROWS_WITH_AS(passes::add_denoiser(g, pipelines, bad, asvgf::DenoiseSettings{}, asvgf::DenoiseMethod::Svgf),
                       doctest::Contains("the albedo 'albedo' is rgba16ui, not a float format or R32Uint"),
                       std::invalid_argument);
}

// A spatial chain's temporal result and colour history are RGB9E5 words (R32Uint), the EMA's RGBA16F,
// and the moments are pack_moments's words (R32Uint): the passes that read or write them refuse a
// mix, or another format, where they are declared.
TEST_CASE(
    "denoise passes: temporal, variance and local-mean passes refuse colour images and moments in the wrong format") {
  ValidatedDevice device;
  passes::PipelineCache pipelines(*device);
  RenderGraph g;
  const auto image = [&g](const char* name, F format) { return g.add_image(name, 8, 8, format); };
  const auto words = image("words", F::R32Uint), halves = image("halves", F::RGBA16F);
  passes::TemporalResources t;
  t.illumination = image("illumination", F::RGBA32F);
  t.motion = image("motion", F::RGBA16F);
  t.depth_normal = g.add_image("depth_normal", 8, 8, F::RGBA16Uint, Lifetime::Persistent);
  t.moments = g.add_image("moments", 8, 8, F::R32Uint, Lifetime::Persistent);
  t.counters = g.add_buffer("counters", 16);
  t.color_history = g.add_image("history.words", 8, 8, F::R32Uint, Lifetime::Persistent);
  t.integrated = halves;
  CHECK_THROWS_AS(passes::add_temporal(g, pipelines, t, {}), std::invalid_argument);
  t.color_history = g.add_image("history.float", 8, 8, F::RGBA32F, Lifetime::Persistent);
  t.integrated = image("integrated.float", F::RGBA32F);
  CHECK_THROWS_AS(passes::add_temporal(g, pipelines, t, {}), std::invalid_argument);
  t.color_history = g.add_image("history.halves", 8, 8, F::RGBA16F, Lifetime::Persistent);
  t.integrated = halves;
  const auto moments = t.moments;
  const auto moments_halves = g.add_image("moments.halves", 8, 8, F::RGBA16F, Lifetime::Persistent);
  t.moments = moments_halves;
  CHECK_THROWS_AS(passes::add_temporal(g, pipelines, t, {}), std::invalid_argument);
  t.moments = moments;
  CHECK_NOTHROW(passes::add_temporal(g, pipelines, t, {}));
  const auto albedo = image("albedo", F::RGBA16F);
  CHECK_THROWS_AS(
      passes::add_variance(g, pipelines, {halves, t.moments, t.depth_normal, image("cv.1", F::RGBA16F), albedo}, {}),
      std::invalid_argument);
  CHECK_THROWS_AS(passes::add_variance(g, pipelines,
                                       {words, moments_halves, t.depth_normal, image("cv.3", F::RGBA16F), albedo}, {}),
                  std::invalid_argument);
  CHECK_NOTHROW(
      passes::add_variance(g, pipelines, {words, t.moments, t.depth_normal, image("cv.2", F::RGBA16F), albedo}, {}));
  asvgf::DenoiseSettings settings;
  settings.local_mean = 3;
  const auto filtered = image("filtered", F::RGBA16F);
  CHECK_THROWS_AS(passes::add_local_mean(g, pipelines, {halves, filtered, image("c.1", F::RGBA16F), "lm.1"}, settings),
                  std::invalid_argument);
  CHECK_THROWS_AS(passes::add_local_mean(g, pipelines, {words, words, image("c.2", F::RGBA16F), "lm.2"}, settings),
                  std::invalid_argument);
  CHECK_NOTHROW(passes::add_local_mean(g, pipelines, {words, filtered, image("c.3", F::RGBA16F), "lm.3"}, settings));
  CHECK_NOTHROW(passes::add_local_mean(g, pipelines, {words, words, image("c.4", F::R32Uint), "lm.4"}, settings));
}

// sigma_n 0 and 0.01 besides the default 128: the tap weight's special cases (a normal facing away
// weighs 0 for any sigma_n > 0, everything 1 for 0), which the shader folds into a clamp and a select.
TEST_CASE(
    "denoise passes: atrous pass matches the CPU reference (B3 spline and box, steps 1, 2, 4, history tap, sigma_n "
    "128, 0 and 0.01 with normals facing away)") {
  ValidatedDevice device;
  passes::PipelineCache pipelines(*device);
  for (const auto kernel : {asvgf::AtrousKernel::B3Spline, asvgf::AtrousKernel::Box}) {
    for (const float sigma_n : {128.0f, 0.0f, 0.01f}) {
      CAPTURE(sigma_n);
      asvgf::DenoiseSettings settings;
      settings.kernel = kernel;
      settings.sigma_n = sigma_n;
      for (const auto& size : kSizes) {
        const int w = size[0], h = size[1];
        Random r(71u + static_cast<std::uint32_t>(w));
        const ImageD dn = random_depth_normal(r, w, h);
        const ImageD color = random_color(r, w, h, 0, 4, 0.5);
        for (int iteration = 0; iteration < 3; ++iteration) {
          CAPTURE(static_cast<int>(kernel));
          CAPTURE(w);
          CAPTURE(iteration);
          const auto uw = static_cast<std::uint32_t>(w), uh = static_cast<std::uint32_t>(h);
          GraphHarness harness(*device);
          RenderGraph g;
          const auto out = g.add_image("atrous_out", uw, uh, F::RGBA16F);
          passes::AtrousResources res{harness.input(g, "color_in", color, F::RGBA16F),
                                      harness.input(g, "depth_normal", depth_normal_texels(dn), F::RGBA16Uint), out,
                                      std::nullopt};
          const bool tap = iteration == 1;
          if (tap) res.color_history = g.add_image("color_history", uw, uh, F::R32Uint, Lifetime::Persistent);
          passes::add_atrous(g, pipelines, res, iteration, settings);
          ImageD got, history;
          harness.readback(g, out, &got);
          if (tap) harness.readback(g, *res.color_history, &history);
          harness.run(g);
          const ImageD want =
              ref::atrous(quantize(color, F::RGBA16F), quantize(dn, F::RGBA32F),
                          {1 << iteration, static_cast<int>(kernel), settings.sigma_z, settings.sigma_n,
                           asvgf::luminance_sigma(settings, std::uint32_t(dn.width), std::uint32_t(dn.height))});
          DENOISE_CHECK_CLOSE(compare(got, want, 4, fp16_tolerance(4)), "atrous");
          if (tap) check_history_words(history, got, "history tap");
        }
      }
    }
  }
}

// Between the first and the last iteration the chain passes packed filter texels (storage buffers
// of 2 words a pixel: colour and variance as halves; and, written once by the first, depth and its
// gradient, normal x, y as halves). Each iteration
// is checked against the reference run on what the previous one wrote (read back and unpacked
// exactly; the first estimates the variance and reads its taps from a shared-memory tile), so the
// tolerance stays one fp16
// store; the packing itself is checked on its own, for normals along every axis and near z = 0.
TEST_CASE(
    "denoise passes: atrous iterations on packed filter texels match the CPU reference, and the packing keeps depth, "
    "normal and depth gradient") {
  ValidatedDevice device;
  passes::PipelineCache pipelines(*device);
  passes::SanitizeCounters counters(*device);
  asvgf::DenoiseSettings settings;
  // And 48x24: workgroups whose taps all lie inside the image at steps 1, 2 and 4 (16x8 and 16x4
  // invocations), which take atrous.comp's workgroup_taps_inside branch.
  constexpr int kPackedSizes[][2] = {{17, 13}, {32, 32}, {9, 5}, {48, 24}};
  for (const auto& size : kPackedSizes) {
    const int w = size[0], h = size[1];
    CAPTURE(w);
    Random r(97u + static_cast<std::uint32_t>(w));
    ImageD dn = random_depth_normal(r, w, h);
    // Normals along each axis, with either sign, and near z = 0 (where rebuilding z from x and y is
    // ill-conditioned).
    const std::array<std::array<double, 3>, 7> kNormals{{{0.3, -0.2, -0.93},
                                                         {-0.9, 0.3, 0.1},
                                                         {0.2, -0.97, 0.05},
                                                         {0.7071, 0.7071, 0.0007},
                                                         {0.7071, 0.7071, -0.0007},
                                                         {0.6, -0.8, 0.0},
                                                         {-0.5774, 0.5773, 0.5774}}};
    for (int y = 0; y < h; y += 2)
      for (int x = 0; x < w; x += 2) {
        const auto oct = asvgf::reference::oct_encode<double>(kNormals[static_cast<std::size_t>(x + 3 * y) % 7]);
        dn.at(x, y, 2) = oct[0], dn.at(x, y, 3) = oct[1];
      }
    // Depth gradients at and past the ends of the packed gradient's range: 0, dz / z below 2^-20,
    // at its smallest and largest codes, and beyond (saturates).
    const std::array<double, 6> kRelativeGradients{0.0, 0x1p-21, 0x1p-20 * 1.125, 3840.0, 1e6, 0x1p-3 * 1.0625};
    for (int x = 0; x < static_cast<int>(kRelativeGradients.size()) && x < w; ++x)
      if (dn.at(x, 1, 0) > 0) dn.at(x, 1, 1) = static_cast<float>(dn.at(x, 1, 0) * kRelativeGradients[std::size_t(x)]);
    dn = depth_normal_as_stored(dn);  // what the texel keeps of them
    const ImageD color = random_color(r, w, h, 0, 4, 0.5);
    const ImageD moments = random_moments(r, w, h);
    const auto uw = static_cast<std::uint32_t>(w), uh = static_cast<std::uint32_t>(h);
    GraphHarness harness(*device);
    RenderGraph g;
    const auto dn_in = harness.input(g, "depth_normal", depth_normal_texels(dn), F::RGBA16Uint);
    const std::uint64_t packed_bytes = std::uint64_t{uw} * uh * 8;
    const auto surface = g.add_buffer("filter_surface", packed_bytes);
    const auto first = g.add_buffer("atrous.1", packed_bytes);
    const auto middle = g.add_buffer("atrous.2", packed_bytes);
    const auto last = g.add_image("atrous.3", uw, uh, F::RGBA16F);
    // A history tap on the first and on a middle iteration (both variants; a chain has one).
    const auto history_first = g.add_image("color_history.1", uw, uh, F::R32Uint, Lifetime::Persistent);
    const auto history = g.add_image("color_history.2", uw, uh, F::R32Uint, Lifetime::Persistent);
    const ImageD estimate_albedo = random_color(r, w, h, 0.05, 1, 1);
    passes::add_atrous(
        g, pipelines,
        {harness.input(g, "integrated", rgb9e5_words(color), F::R32Uint), dn_in, first, history_first, "", surface,
         passes::VarianceEstimateInputs{harness.input(g, "moments", moments_words(moments), F::R32Uint),
                                        harness.input(g, "estimate_albedo", estimate_albedo, F::RGBA16F)}},
        0, settings);
    passes::add_atrous(g, pipelines, {first, dn_in, middle, history, "", surface}, 1, settings);
    passes::add_atrous(g, pipelines, {middle, dn_in, last, std::nullopt, "", surface}, 2, settings);
    // The same last iteration compositing itself, with a history tap on every other size.
    const ImageD albedo = random_color(r, w, h, 0, 1, 1);
    const auto hdr = g.add_image("hdr", uw, uh, F::RGBA32F), display = g.add_image("display", uw, uh, F::RGBA8Unorm);
    const bool composite_tap = w % 2 == 1;
    const auto history_last = g.add_image("color_history.3", uw, uh, F::R32Uint, Lifetime::Persistent);
    passes::add_atrous(
        g, pipelines,
        {middle, dn_in, 0, composite_tap ? std::optional(history_last) : std::nullopt, "", surface, std::nullopt,
         passes::CompositeResources{0, harness.input(g, "albedo", albedo, F::RGBA16F), hdr, display,
                                    counters.import(g)}},
        2, settings);
    // The same compositing iteration with half-float radiance (HDR_HALF), with the history tap where
    // the other has none (both variants over the sizes).
    const auto hdr_half = g.add_image("hdr.half", uw, uh, F::RGBA16F);
    const auto history_half = g.add_image("color_history.half", uw, uh, F::R32Uint, Lifetime::Persistent);
    passes::AtrousResources last_half{
        middle,
        dn_in,
        0,
        composite_tap ? std::nullopt : std::optional(history_half),
        "",
        surface,
        std::nullopt,
        passes::CompositeResources{0, harness.input(g, "albedo.half", albedo, F::RGBA16F), hdr_half,
                                   g.add_image("display.half", uw, uh, F::RGBA8Unorm), counters.import(g)}};
    last_half.name_suffix = ".half";
    passes::add_atrous(g, pipelines, last_half, 2, settings);
    ImageD got_first, got_middle, got_surface, got_last, got_history_first, got_history, got_hdr, got_display,
        got_history_last, got_hdr_half;
    harness.readback(g, hdr, &got_hdr);
    harness.readback(g, hdr_half, &got_hdr_half);
    harness.readback(g, display, &got_display);
    if (composite_tap) harness.readback(g, history_last, &got_history_last);
    harness.readback_buffer(g, first, w, h, 2, &got_first);
    harness.readback_buffer(g, middle, w, h, 2, &got_middle);
    harness.readback_buffer(g, surface, w, h, 2, &got_surface);
    harness.readback(g, last, &got_last);
    harness.readback(g, history_first, &got_history_first);
    harness.readback(g, history, &got_history);
    harness.run(g);
    const ImageD dn_q = quantize(dn, F::RGBA32F);
    const FilterTexels t1 = unpack_filter_texels(got_first, got_surface),
                       t2 = unpack_filter_texels(got_middle, got_surface);
    const auto params = [&](int iteration) {
      return ref::AtrousParams{1 << iteration, 0, settings.sigma_z, settings.sigma_n,
                               asvgf::luminance_sigma(settings, std::uint32_t(dn.width), std::uint32_t(dn.height))};
    };
    // The first iteration estimates the variance (the variance pass's reference) as it loads its
    // tile, so it inherits that estimate's tolerance (the variance pass's test: fp16_tolerance(80));
    // the a-trous average over normalised weights adds its own rounding, not a larger error. The
    // tile keeps the estimate in fp32, and so does the reference: rounded to fp16 as the variance
    // pass's image would be, it put the variance channel at 0.98 of the tolerance on these images
    // and past it (1.02) on others, against 0.31-0.45 unrounded.
    const ImageD color_variance = ref::variance(
        rgb9e5_values(rgb9e5_words(color)), moments_values(moments_words(moments)), dn_q,
        quantize(estimate_albedo, F::RGBA16F),
        {settings.sigma_z, settings.sigma_n,
         asvgf::luminance_sigma(settings, std::uint32_t(dn.width), std::uint32_t(dn.height)), settings.min_history});
    DENOISE_CHECK_CLOSE(compare(t1.color, ref::atrous(color_variance, dn_q, params(0)), 4, fp16_tolerance(80)),
                        "first iteration");
    DENOISE_CHECK_CLOSE(compare(t2.color, ref::atrous(t1.color, t1.depth_normal, params(1)), 4, fp16_tolerance(4)),
                        "middle iteration");
    DENOISE_CHECK_CLOSE(compare(got_last, ref::atrous(t2.color, t2.depth_normal, params(2)), 4, fp16_tolerance(4)),
                        "last iteration");
    // Composited from the same result unrounded: it differs from the image's fp16 value by at most
    // half an ulp of the light, which times an albedo <= 1 is within two ulps of the radiance.
    const auto want =
        ref::composite(got_last, quantize(albedo, F::RGBA16F), settings.exposure, static_cast<int>(settings.tonemap));
    DENOISE_CHECK_CLOSE(compare(got_hdr, want.hdr, 3, [](double v) { return 2 * fp16_ulp(v) + 1e-5; }),
                        "last iteration's composite hdr");
    // The half-float radiance: the float one rounded to the nearest half (below 2^-14 the last bit
    // is the store's).
    DENOISE_CHECK_CLOSE(compare(got_hdr_half, got_hdr, 3, [](double v) { return 0.5 * fp16_ulp(v) + 0x1p-24; }),
                        "last iteration's composite hdr, half floats");
    DENOISE_CHECK_CLOSE(compare(got_display, want.display, 3, [](double) { return 1.0 / 255.0; }),
                        "last iteration's composite display");
    // The same fp32 result, stored as RGB9E5 words and by the image format or packHalf2x16.
    if (composite_tap) check_history_words(got_history_last, got_last, "last history tap");
    check_history_words(got_history_first, t1.color, "first history tap");
    check_history_words(got_history, t2.color, "middle history tap");
    // Depth to the bit; normal x and y within one fp16 ulp (2^-11 below 1: a device may round
    // toward zero), z rebuilt within min(sqrt(d), d / |z|) for d = 1.4e-3 (the largest change of
    // 1 - x^2 - y^2, 2 (|x| + |y|) 2^-11), which also holds its sign wherever |z| exceeds the bound;
    // the next iteration passes both on unchanged.
    int packing_errors = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const double z = dn_q.at(x, y, 0);
        const auto n = asvgf::reference::oct_decode<double>({dn_q.at(x, y, 2), dn_q.at(x, y, 3)});
        const auto packed =
            asvgf::reference::oct_decode<double>({t1.depth_normal.at(x, y, 2), t1.depth_normal.at(x, y, 3)});
        const bool depth_kept = t1.depth_normal.at(x, y, 0) == z && t2.depth_normal.at(x, y, 0) == z;
        constexpr double kXy = 1.0 / 2048, kD = 1.4e-3;
        const double z_bound = std::min(std::sqrt(kD), kD / std::abs(n[2]));
        bool normal_kept = z == 0.0 || (std::abs(packed[0] - n[0]) <= kXy && std::abs(packed[1] - n[1]) <= kXy &&
                                        std::abs(packed[2] - n[2]) <= z_bound);
        normal_kept = normal_kept && t2.depth_normal.at(x, y, 2) == t1.depth_normal.at(x, y, 2) &&
                      t2.depth_normal.at(x, y, 3) == t1.depth_normal.at(x, y, 3);
        if (!depth_kept || !normal_kept) ++packing_errors;
      }
    CHECK(packing_errors == 0);
    // The centre's depth gradient, 8 bits of the packed depth word: dz / z within 1/16 of itself
    // (common/filter_texel.glsl), 0 below 2^-20 (rounded), 3840 above; passed on unchanged.
    int gradient_errors = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const double z = dn_q.at(x, y, 0), want_r = z > 0 ? dn_q.at(x, y, 1) / z : 0.0;
        const double got = z > 0 ? t1.depth_normal.at(x, y, 1) / z : t1.depth_normal.at(x, y, 1);
        const bool kept = want_r < 0x1p-20 * 1.0625
                              ? got == 0.0  // rounds to the smallest code's value: 0
                              : std::abs(got - std::min(want_r, 3840.0)) <= std::min(want_r, 3840.0) / 16;
        gradient_errors += !kept || t2.depth_normal.at(x, y, 1) != t1.depth_normal.at(x, y, 1);
      }
    CHECK(gradient_errors == 0);
  }
  // The shared-memory tile that writes the first packed texels assumes step 1.
  RenderGraph g;
  const auto img = g.add_image("color_in", 8, 8, F::RGBA16F), dn = g.add_image("depth_normal", 8, 8, F::RGBA16Uint);
  const auto alb = g.add_image("albedo", 8, 8, F::RGBA16F);
  const passes::VarianceEstimateInputs mom{g.add_image("moments", 8, 8, F::R32Uint), alb};
  // The first packed iteration's temporal result: RGB9E5 words, as a spatial chain keeps it.
  const auto words = g.add_image("integrated", 8, 8, F::R32Uint);
  const auto packed = [&](const char* name, std::uint64_t bytes) { return g.add_buffer(name, bytes); };
  const auto surface = packed("surface", 8 * 8 * 8);
  CHECK_THROWS_AS(passes::add_atrous(
                      g, pipelines, {words, dn, packed("out", 8 * 8 * 8), std::nullopt, "", surface, mom}, 1, settings),
                  std::invalid_argument);
  // A packed iteration writes or reads the surface texels: without their buffer the chain has none.
  CHECK_THROWS_AS(
      passes::add_atrous(
          g, pipelines, {words, dn, packed("no_surface", 8 * 8 * 8), std::nullopt, "", std::nullopt, mom}, 0, settings),
      std::invalid_argument);
  // The first packed iteration estimates the variance from the moments and albedo; no other reads them.
  CHECK_THROWS_AS(
      passes::add_atrous(g, pipelines, {words, dn, packed("no_moments", 8 * 8 * 8), std::nullopt, "", surface}, 0,
                         settings),
      std::invalid_argument);
  CHECK_THROWS_AS(
      passes::add_atrous(g, pipelines,
                         {img, dn, g.add_image("image_out", 8, 8, F::RGBA16F), std::nullopt, "", std::nullopt, mom}, 0,
                         settings),
      std::invalid_argument);
  // A buffer or image that does not cover depth_normal would be read or written out of range.
  CHECK_THROWS_AS(
      passes::add_atrous(g, pipelines, {words, dn, packed("small", 8 * 8 * 8 - 8), std::nullopt, "", surface, mom}, 0,
                         settings),
      std::invalid_argument);
  CHECK_THROWS_AS(passes::add_atrous(g, pipelines,
                                     {words, dn, packed("out.2", 8 * 8 * 8), std::nullopt, "",
                                      packed("small_surface", 8 * 8 * 8 - 8), mom},
                                     0, settings),
                  std::invalid_argument);
  CHECK_THROWS_AS(passes::add_atrous(g, pipelines, {img, dn, g.add_image("wide", 9, 8, F::RGBA16F)}, 0, settings),
                  std::invalid_argument);
  // The first packed iteration with the variance estimate's inputs given.
  const auto first_with = [&](const char* out, const passes::VarianceEstimateInputs& estimate) {
    return passes::add_atrous(g, pipelines, {words, dn, packed(out, 8 * 8 * 8), std::nullopt, "", surface, estimate}, 0,
                              settings);
  };
  CHECK_THROWS_AS(first_with("narrow_moments", {g.add_image("moments.small", 7, 8, F::R32Uint), alb}),
                  std::invalid_argument);
  CHECK_THROWS_AS(first_with("narrow_albedo", {mom.moments, g.add_image("albedo.small", 8, 7, F::RGBA16F)}),
                  std::invalid_argument);
  // The moments as RGBA16F (not pack_moments's words).
  CHECK_THROWS_AS(first_with("halves_moments", {g.add_image("moments.halves", 8, 8, F::RGBA16F), alb}),
                  std::invalid_argument);
  CHECK_NOTHROW(passes::add_atrous(g, pipelines, {words, dn, packed("fits", 8 * 8 * 8), std::nullopt, "", surface, mom},
                                   0, settings));
  // The temporal result and the colour history in another format than RGB9E5 words.
  CHECK_THROWS_AS(
      passes::add_atrous(g, pipelines, {img, dn, packed("rgba16f_in", 8 * 8 * 8), std::nullopt, "", surface, mom}, 0,
                         settings),
      std::invalid_argument);
  CHECK_THROWS_AS(passes::add_atrous(g, pipelines,
                                     {words, dn, packed("rgba16f_history", 8 * 8 * 8),
                                      g.add_image("history.rgba16f", 8, 8, F::RGBA16F), "", surface, mom},
                                     0, settings),
                  std::invalid_argument);
  // The local mean's block sums: from the first packed iteration only with its history tap, and in
  // blocks of 1, 2, 4 or 8 pixels (whole blocks inside a workgroup).
  const auto sums = g.add_image("sums", 8, 8, F::RGBA32F), history = g.add_image("history", 8, 8, F::R32Uint);
  passes::AtrousResources middle{
      packed("middle_in", 8 * 8 * 8), dn, packed("middle_out", 8 * 8 * 8), std::nullopt, "", surface};
  middle.local_mean_sums = {sums, std::nullopt, 1};
  CHECK_THROWS_AS(passes::add_atrous(g, pipelines, middle, 1, settings), std::invalid_argument);
  // The history's correction: a packed middle iteration, which writes color_history.
  middle.local_mean_sums.reset();
  middle.corrects_history = {g.add_image("box_means", 8, 8, F::RGBA32F), 1, 2};
  CHECK_THROWS_AS(passes::add_atrous(g, pipelines, middle, 1, settings), std::invalid_argument);
  middle.color_history = history;
  CHECK_NOTHROW(passes::add_atrous(g, pipelines, middle, 1, settings));
  passes::AtrousResources block3{words, dn, packed("block3", 8 * 8 * 8), history, "", surface, mom};
  block3.local_mean_sums = {sums, std::nullopt, 3};
  CHECK_THROWS_AS(passes::add_atrous(g, pipelines, block3, 0, settings), std::invalid_argument);
  block3.local_mean_sums->block = 2;
  CHECK_NOTHROW(passes::add_atrous(g, pipelines, block3, 0, settings));
}

// The local-mean correction (--local-mean): block sums, a box over blocks and a bilinear read, against
// the reference's direct sums. Blocks of 1 (k 3, 9: a plain k x k box), 2, 4 and 8 pixels, windows
// larger than the image, clamped at its edges and across workgroups, a black neighbourhood (left as
// it is), the gate and the plain ratio.
TEST_CASE(
    "denoise passes: the local-mean correction matches the CPU reference (blocks of 1 to 8 pixels, gated and plain, "
    "windows clamped at the edges and across workgroups, a black neighbourhood left unscaled), and the same bits from "
    "another correction's temporal block sums and from the composite's own correction") {
  ValidatedDevice device;
  passes::PipelineCache pipelines(*device);
  passes::SanitizeCounters counters(*device);
  // 23x17: partial blocks at the right and bottom edges, a window wider than the image (k 65);
  // 300x70: windows cross workgroups, blocks of 2 (k 17), 4 (k 33) and 8 (k 255).
  struct Case {
    int w, h, k;
  };
  for (const Case c :
       {Case{23, 17, 3}, Case{23, 17, 9}, Case{23, 17, 65}, Case{300, 70, 17}, Case{300, 70, 33}, Case{300, 70, 255}}) {
    for (const bool gated : {true, false}) {
      const int w = c.w, h = c.h, k = c.k;
      CAPTURE(w);
      CAPTURE(k);
      CAPTURE(gated);
      Random r(131u + static_cast<std::uint32_t>(k));
      // The temporal result brighter than the filtered one on average, as where the filter lost energy.
      ImageD temporal = random_color(r, w, h, 0, 4, 1), filtered = random_color(r, w, h, 0, 3, 1);
      for (int y = 0; y < 4; ++y)  // a black corner: nothing filtered to scale there
        for (int x = 0; x < 4; ++x)
          for (int ch = 0; ch < 3; ++ch) filtered.at(x, y, ch) = temporal.at(x, y, ch) = 0;
      asvgf::DenoiseSettings settings;
      settings.local_mean = k;
      GraphHarness harness(*device);
      RenderGraph g;
      const auto corrected = g.add_image("corrected", w, h, F::RGBA16F);
      // The temporal result as a spatial chain keeps it: RGB9E5 words.
      const ImageD temporal_words = rgb9e5_words(temporal);
      const auto temporal_id = harness.input(g, "temporal", temporal_words, F::R32Uint);
      const auto filtered_id = harness.input(g, "filtered", filtered, F::RGBA16F);
      const passes::LocalMeanImages images =
          passes::add_local_mean(g, pipelines, {temporal_id, filtered_id, corrected, "local_mean", gated}, settings);
      // The tapped history's correction: the filtered colour read and the corrected one written as
      // RGB9E5 words, as the colour history is kept.
      const ImageD filtered_words = rgb9e5_words(filtered);
      const auto corrected_words = g.add_image("corrected.words", w, h, F::R32Uint);
      passes::add_local_mean(g, pipelines,
                             {temporal_id, harness.input(g, "filtered.words", filtered_words, F::R32Uint),
                              corrected_words, "local_mean.words", gated},
                             settings);
      // The displayed colour's correction as the denoiser builds it: the temporal terms from the
      // first correction's block sums (its own temporal input left black, so that reading it would
      // show), applied by the composite (albedo 1, clamp curve: HDR radiance is the corrected colour).
      const auto shared = g.add_image("corrected_shared", w, h, F::RGBA16F);
      const auto black = harness.input(g, "black", ImageD(w, h, 1), F::R32Uint);
      const passes::LocalMeanImages second = passes::add_local_mean(
          g, pipelines, {black, filtered_id, shared, "local_mean.shared", gated, images.block_sums}, settings);
      ImageD got, got_shared, got_hdr, got_hdr_rgb9e5, want_rgb9e5, got_hdr_half, got_words;
      if (gated) {
        const auto hdr = g.add_image("hdr", w, h, F::RGBA32F);
        const auto albedo_id = harness.input(g, "albedo", ImageD(w, h, 4, 1.0), F::RGBA16F);
        passes::add_composite(g, pipelines,
                              {filtered_id, albedo_id, hdr, g.add_image("display", w, h, F::RGBA8Unorm),
                               counters.import(g), std::nullopt, std::nullopt, second},
                              settings);
        harness.readback(g, hdr, &got_hdr);
        // The same with half-float radiance (HDR_HALF): the corrected colour is a half already.
        const auto hdr_half = g.add_image("hdr.half", w, h, F::RGBA16F);
        passes::add_composite(g, pipelines,
                              {filtered_id, albedo_id, hdr_half, g.add_image("display.half", w, h, F::RGBA8Unorm),
                               counters.import(g), std::nullopt, std::nullopt, second},
                              settings);
        harness.readback(g, hdr_half, &got_hdr_half);
        // The same correction of the filtered colour read as RGB9E5 (a last a-trous iteration's
        // RGB9E5_OUT), with the box means of the fp16 colour's sums: the correction pass over the
        // values the words hold, with those sums.
        const ImageD words = rgb9e5_words(quantize(filtered, F::RGBA16F));
        const auto hdr_rgb9e5 = g.add_image("hdr.rgb9e5", w, h, F::RGBA32F);
        passes::add_composite(g, pipelines,
                              {harness.input(g, "filtered.rgb9e5", words, F::R32Uint), albedo_id, hdr_rgb9e5,
                               g.add_image("display.rgb9e5", w, h, F::RGBA8Unorm), counters.import(g), std::nullopt,
                               std::nullopt, second},
                              settings);
        const auto corrected_values = g.add_image("corrected.rgb9e5", w, h, F::RGBA16F);
        passes::LocalMeanResources values{black, harness.input(g, "filtered.values", rgb9e5_values(words), F::RGBA16F),
                                          corrected_values, "local_mean.rgb9e5", gated};
        values.block_sums = second.block_sums;
        passes::add_local_mean(g, pipelines, values, settings);
        harness.readback(g, hdr_rgb9e5, &got_hdr_rgb9e5);
        harness.readback(g, corrected_values, &want_rgb9e5);
      }
      harness.readback(g, corrected, &got);
      harness.readback(g, shared, &got_shared);
      harness.readback(g, corrected_words, &got_words);
      harness.run(g);
      const passes::LocalMeanBlocks blocks = passes::local_mean_blocks(k);
      if (k < 16) CHECK(blocks.block == 1);  // small windows are plain k x k boxes
      const ImageD temporal_values = rgb9e5_values(temporal_words);
      const ImageD want =
          ref::local_mean(temporal_values, quantize(filtered, F::RGBA16F), blocks.block, blocks.radius, gated);
      DENOISE_CHECK_CLOSE(compare(got, want, 4, fp16_tolerance(4)), "local mean");
      const ImageD want_words =
          ref::local_mean(temporal_values, rgb9e5_values(filtered_words), blocks.block, blocks.radius, gated);
      DENOISE_CHECK_CLOSE(compare(rgb9e5_values(got_words), want_words, 3, rgb9e5_tolerance(got_words, 4)),
                          "local mean of RGB9E5 words");
      CHECK(rgb9e5_not_canonical(got_words) == 0);
      if (k == 3) CHECK(got.at(1, 1, 0) == 0.0);  // inside the black corner: 0 stays 0, no NaN
      // The shared temporal sums and the composite's own correction change nothing: the same bits.
      const auto exact = [](double) { return 1.0; };
      CHECK(compare(got_shared, got, 4, exact).worst_error == 0.0);
      if (gated) CHECK(compare(got_hdr, got, 3, exact).worst_error == 0.0);
      if (gated) CHECK(compare(got_hdr_half, got, 3, exact).worst_error == 0.0);
      if (gated) CHECK(compare(got_hdr_rgb9e5, want_rgb9e5, 3, exact).worst_error == 0.0);
    }
  }
}

// The local mean's block sums from the a-trous iterations themselves (atrous.hpp's LocalMeanSums):
// the first packed iteration's, with the history tap and without (the temporal result's terms and its own), and a
// packed-in last iteration's (its own, the temporal terms from the first's), against the blocks
// pass over the images those iterations write: the same sums in the same order, bit for bit. And the
// history corrected by the next iteration (HistoryCorrection) against the correction's own pass: the
// same fp32 values, stored as RGB9E5 words by the one and rounded to halves by the other.
TEST_CASE(
    "denoise passes: the a-trous iterations' local-mean block sums are the blocks pass's, bit for bit, and the "
    "history they correct is the correction pass's within its RGB9E5 rounding (blocks of 1 to 8 pixels, partial "
    "blocks at the edges, several workgroups)") {
  ValidatedDevice device;
  passes::PipelineCache pipelines(*device);
  for (const auto& size : {std::array<int, 2>{37, 21}, std::array<int, 2>{70, 35}}) {
    for (const int k : {3, 17, 33, 65}) {
      const int w = size[0], h = size[1];
      CAPTURE(w);
      CAPTURE(k);
      Random r(211u + static_cast<std::uint32_t>(w + k));
      const ImageD dn = depth_normal_as_stored(random_depth_normal(r, w, h));
      const ImageD color = random_color(r, w, h, 0, 4, 0.5);
      const ImageD moments = random_moments(r, w, h);
      const ImageD albedo = random_color(r, w, h, 0.05, 1, 1);
      asvgf::DenoiseSettings settings;
      settings.local_mean = k;
      const int block = passes::local_mean_blocks(k).block;
      const auto uw = static_cast<std::uint32_t>(w), uh = static_cast<std::uint32_t>(h);
      GraphHarness harness(*device);
      RenderGraph g;
      const auto dn_in = harness.input(g, "depth_normal", depth_normal_texels(dn), F::RGBA16Uint);
      const ImageD words = rgb9e5_words(color);  // the temporal result, as a spatial chain keeps it
      const auto integrated = harness.input(g, "integrated", words, F::R32Uint);
      const std::uint64_t packed_bytes = std::uint64_t{uw} * uh * 8;
      const auto surface = g.add_buffer("filter_surface", packed_bytes);
      const auto first = g.add_buffer("atrous.1", packed_bytes), middle = g.add_buffer("atrous.2", packed_bytes);
      const auto last = g.add_image("atrous.3", uw, uh, F::RGBA16F);
      const auto history = g.add_image("color_history", uw, uh, F::R32Uint, Lifetime::Persistent);
      const auto history_sums = passes::add_local_mean_sums_image(g, "history", uw, uh, k);
      const auto display_sums = passes::add_local_mean_sums_image(g, "display", uw, uh, k);
      passes::AtrousResources a1{
          integrated,
          dn_in,
          first,
          history,
          "",
          surface,
          passes::VarianceEstimateInputs{harness.input(g, "moments", moments_words(moments), F::R32Uint),
                                         harness.input(g, "albedo", albedo, F::RGBA16F)}};
      a1.local_mean_sums = {history_sums, std::nullopt, block};
      passes::add_atrous(g, pipelines, a1, 0, settings);
      // The same first iteration without the history tap (the variant the default graph runs, whose
      // next iteration writes the history): the same sums.
      passes::AtrousResources a1_untapped = a1;
      a1_untapped.color_out = g.add_buffer("atrous.1.untapped", packed_bytes);
      a1_untapped.color_history.reset();
      a1_untapped.surface = g.add_buffer("filter_surface.untapped", packed_bytes);
      const auto untapped_sums = passes::add_local_mean_sums_image(g, "history.untapped", uw, uh, k);
      a1_untapped.local_mean_sums = {untapped_sums, std::nullopt, block};
      passes::add_atrous(g, pipelines, a1_untapped, 0, settings);
      // The second iteration writes the corrected history itself (atrous.hpp's HistoryCorrection),
      // with the box means of the first iteration's sums, as the denoiser's graph does (below).
      const auto history_corrected = g.add_image("color_history.corrected", uw, uh, F::R32Uint);
      passes::AtrousResources a2{first, dn_in, middle, history_corrected, "", surface};
      const passes::LocalMeanBlocks lmb = passes::local_mean_blocks(k);
      passes::AtrousResources a3{middle, dn_in, last, std::nullopt, "", surface};
      a3.local_mean_sums = {display_sums, history_sums, block};
      // The box pass over the first iteration's sums; the blocks passes over the images the
      // iterations wrote are below (the history's: a second graph over the first iteration's colour).
      passes::LocalMeanResources history_box{integrated, history, history, "history", false};
      history_box.block_sums = history_sums;
      history_box.apply_pass = false;
      const auto box = passes::add_local_mean(g, pipelines, history_box, settings);
      a2.corrects_history = {box.box_means, lmb.block, lmb.radius};
      passes::add_atrous(g, pipelines, a2, 1, settings);
      passes::add_atrous(g, pipelines, a3, 2, settings);
      // The same last iteration writing its colour as RGB9E5 for the composite (RGB9E5_OUT).
      passes::AtrousResources a3_rgb9e5 = a3;
      a3_rgb9e5.color_out = g.add_image("atrous.3.rgb9e5", uw, uh, F::R32Uint);
      const auto display_sums_rgb9e5 = passes::add_local_mean_sums_image(g, "display.rgb9e5", uw, uh, k);
      a3_rgb9e5.local_mean_sums = {display_sums_rgb9e5, history_sums, block};
      a3_rgb9e5.name_suffix = ".rgb9e5";
      passes::add_atrous(g, pipelines, a3_rgb9e5, 2, settings);
      const auto want_display = passes::add_local_mean(
          g, pipelines, {integrated, last, g.add_image("corrected", uw, uh, F::RGBA16F), "ref", true, history_sums},
          settings);
      ImageD got_h, got_untapped, got_d, want_h, want_d, got_history, want_history_image, got_first, got_surface;
      harness.readback(g, untapped_sums, &got_untapped);
      harness.readback(g, history_corrected, &got_history);
      harness.readback_buffer(g, first, w, h, 2, &got_first);
      harness.readback_buffer(g, surface, w, h, 2, &got_surface);
      harness.readback(g, history_sums, &got_h);
      harness.readback(g, display_sums, &got_d);
      ImageD got_d_rgb9e5, got_last, got_last_words;
      harness.readback(g, display_sums_rgb9e5, &got_d_rgb9e5);
      harness.readback(g, last, &got_last);
      harness.readback(g, a3_rgb9e5.color_out, &got_last_words);
      harness.readback(g, want_display.block_sums, &want_d);
      harness.run(g);
      // The history's correction by its own passes over the first iteration's colour (the packed
      // texels' halves, which its sums and the second iteration read): blocks, box, and the plain
      // RGBA16F correction, which rounds the same fp32 values to halves.
      RenderGraph g2;
      const auto first_color =
          harness.input(g2, "atrous.1.color", unpack_filter_texels(got_first, got_surface).color, F::RGBA16F);
      const auto corrected_history = g2.add_image("corrected.history", uw, uh, F::RGBA16F);
      const auto want_history = passes::add_local_mean(
          g2, pipelines,
          {harness.input(g2, "integrated", words, F::R32Uint), first_color, corrected_history, "ref.history", false},
          settings);
      harness.readback(g2, want_history.block_sums, &want_h);
      harness.readback(g2, corrected_history, &want_history_image);
      harness.run(g2);
      const auto exact = [](double) { return 1.0; };
      REQUIRE(got_h.width == (w + block - 1) / block);
      CHECK(compare(got_h, want_h, 4, exact).worst_error == 0.0);
      CHECK(compare(got_untapped, want_h, 4, exact).worst_error == 0.0);
      CHECK(compare(got_d, want_d, 4, exact).worst_error == 0.0);
      // The RGB9E5 twin: the same sums (of its fp16-rounded result), the colour within its rounding.
      CHECK(compare(got_d_rgb9e5, want_d, 4, exact).worst_error == 0.0);
      DENOISE_CHECK_CLOSE(compare(rgb9e5_values(got_last_words), got_last, 3, rgb9e5_tolerance(got_last_words, 0)),
                          "last iteration's RGB9E5 colour");
      CHECK(rgb9e5_not_canonical(got_last_words) == 0);
      check_history_words(got_history, want_history_image, "corrected history");
      CHECK(want_h.at(0, 0, 3) == double(std::min(block, h) * std::min(block, w)));  // a whole block's pixels
    }
  }
}

TEST_CASE(
    "denoise passes: composite pass matches the CPU reference (clamp and ACES tone curves, RGBA32F and RGBA16F "
    "radiance, one signal and the specular split), zeroes and counts non-finite radiance") {
  ValidatedDevice device;
  passes::PipelineCache pipelines(*device);
  passes::SanitizeCounters counters(*device);
  for (const auto& [tonemap, hdr_format] : {std::pair{asvgf::Tonemap::Clamp, F::RGBA32F},
                                            {asvgf::Tonemap::Aces, F::RGBA32F},
                                            {asvgf::Tonemap::Clamp, F::RGBA16F},
                                            {asvgf::Tonemap::Aces, F::RGBA16F}}) {
    const bool half = hdr_format == F::RGBA16F;
    CAPTURE(half);
    const int w = 17, h = 13;
    Random r(91);
    ImageD illumination = random_color(r, w, h, 0, 3, 0);
    ImageD albedo = random_color(r, w, h, 0, 1, 1);
    albedo.at(3, 3, 0) = 0;  // the demodulation guard
    illumination.at(4, 4, 1) = std::numeric_limits<double>::quiet_NaN();
    illumination.at(5, 2, 0) = std::numeric_limits<double>::infinity();
    asvgf::DenoiseSettings settings;
    settings.tonemap = tonemap;
    settings.exposure = 1.5f;
    GraphHarness harness(*device);
    RenderGraph g;
    const auto hdr = g.add_image("hdr", w, h, hdr_format);
    const auto display = g.add_image("display", w, h, F::RGBA8Unorm);
    const auto illumination_id = harness.input(g, "illumination", illumination, F::RGBA32F);
    const auto albedo_id = harness.input(g, "albedo", albedo, F::RGBA16F);
    passes::add_composite(g, pipelines, {illumination_id, albedo_id, hdr, display, counters.import(g)}, settings);
    // The specular split (SPLIT): the filtered specular light re-modulated by its own albedo, added.
    const ImageD specular = random_color(r, w, h, 0, 3, 0);
    ImageD specular_albedo = random_color(r, w, h, 0, 1, 1);
    specular_albedo.at(6, 6, 2) = 0;  // its demodulation guard
    const auto hdr_split = g.add_image("hdr.split", w, h, hdr_format);
    const auto display_split = g.add_image("display.split", w, h, F::RGBA8Unorm);
    passes::add_composite(g, pipelines,
                          {illumination_id, albedo_id, hdr_split, display_split, counters.import(g),
                           harness.input(g, "specular", specular, F::RGBA32F),
                           harness.input(g, "specular_albedo", specular_albedo, F::RGBA16F)},
                          settings);
    ImageD got_hdr, got_display, got_hdr_split, got_display_split;
    harness.readback(g, hdr, &got_hdr);
    harness.readback(g, display, &got_display);
    harness.readback(g, hdr_split, &got_hdr_split);
    harness.readback(g, display_split, &got_display_split);
    harness.run(g);
    const ImageD light = quantize(illumination, F::RGBA32F), albedo_q = quantize(albedo, F::RGBA16F);
    const auto want = ref::composite(light, albedo_q, settings.exposure, static_cast<int>(tonemap));
    // RGBA16F: rounded to the nearest half (below 2^-14 the last bit is the store's: one ulp there).
    const auto hdr_tolerance = [half](double v) { return (half ? fp16_ulp(v) : 0.0) + 1e-5 * 6; };
    DENOISE_CHECK_CLOSE(compare(got_hdr, want.hdr, 4, hdr_tolerance), "composite hdr");
    DENOISE_CHECK_CLOSE(compare(got_display, want.display, 4, [](double) { return 1.0 / 255.0; }), "composite display");
    CHECK(got_hdr.at(4, 4, 1) == 0.0);
    CHECK(got_hdr.at(5, 2, 0) == 0.0);
    // The split's radiance as one signal of albedo 1: the reference's tone curve then applies to it.
    ImageD both(w, h, 4), ones(w, h, 4, 1.0);
    const ImageD specular_albedo_q = quantize(specular_albedo, F::RGBA16F);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        for (int c = 0; c < 3; ++c)
          both.at(x, y, c) = light.at(x, y, c) * std::max(albedo_q.at(x, y, c), 1e-3) +
                             specular.at(x, y, c) * std::max(specular_albedo_q.at(x, y, c), 1e-3);
    const auto want_split = ref::composite(both, ones, settings.exposure, static_cast<int>(tonemap));
    DENOISE_CHECK_CLOSE(compare(got_hdr_split, want_split.hdr, 4, hdr_tolerance), "composite hdr, split");
    DENOISE_CHECK_CLOSE(compare(got_display_split, want_split.display, 4, [](double) { return 1.0 / 255.0; }),
                        "composite display, split");
    CHECK(got_hdr_split.at(4, 4, 1) == 0.0);
  }
  // Two non-finite pixels a frame in each of the two composites, four frames; nothing else.
  const auto counts = counters.read();
  CHECK(counts.zeroed_outputs == 16);
  CHECK(counts.clamped_samples == 0);
}
