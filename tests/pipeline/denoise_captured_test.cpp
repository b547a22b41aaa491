// The temporal and a-trous passes against their CPU references on inputs captured from the
// built-in scene (orbit: the camera moves, so reprojection follows real motion vectors), instead of
// random ones. Tolerances as in denoise_passes_test.cpp: one fp16 ulp per store plus fp32
// arithmetic (1e-5 x the magnitude of what is summed).
#include <doctest/doctest.h>

#include "asvgf/sanitize_counters.hpp"
#include "cpu_oracle/denoise_reference.hpp"
#include "denoiser/passes/atrous.hpp"
#include "denoiser/passes/temporal.hpp"
#include "frame_inputs.hpp"
#include "pipeline/denoise_harness.hpp"
#include "renderer/scene/builtin.hpp"
#include "vulkan/validated_device.hpp"

using namespace denoise_test;
using asvgf::graph::Lifetime;
using asvgf::graph::RenderGraph;
using F = hal::Format;
namespace ref = asvgf::reference;
namespace passes = asvgf::passes;

namespace {

constexpr int kW = 32, kH = 24;

ImageD to_image(const std::vector<float>& values) {
  ImageD img(kW, kH, 4);
  for (std::size_t i = 0; i < values.size(); ++i) img.data[i] = values[i];
  return img;
}

// Colour with a variance estimate in alpha (a tenth of the squared luminance).
ImageD with_variance(const std::vector<float>& rgb) {
  ImageD img = to_image(rgb);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const double l = 0.2126 * img.at(x, y, 0) + 0.7152 * img.at(x, y, 1) + 0.0722 * img.at(x, y, 2);
      img.at(x, y, 3) = 0.1 * l * l;
    }
  return img;
}

// Clamp like the temporal pass's sanitiser, so that a lone bright sample does not set the scale.
double magnitude(const ImageD& img) {
  double m = 0;
  for (double v : img.data) m = std::max(m, std::min(std::abs(v), 65504.0));
  return m;
}

}  // namespace

TEST_CASE("denoise passes: temporal and atrous match the CPU reference on frames captured from the built-in scene") {
  ValidatedDevice device;
  const auto scene = asvgf::scene::builtin_scene("cornell", "orbit");
  const FrameInputs prev = render_frame_inputs(*device, scene, device->capabilities().ray_query, kW, kH, 5);
  const FrameInputs cur = render_frame_inputs(*device, scene, device->capabilities().ray_query, kW, kH, 6);

  SUBCASE("temporal (constant alpha) reprojects along the captured motion") {
    passes::PipelineCache pipelines(*device);
    asvgf::DenoiseSettings settings;
    passes::SanitizeCounters counters(*device);
    GraphHarness harness(*device);
    const ImageD prev_dn = to_image(prev.depth_normal), dn_now = to_image(cur.depth_normal);
    const ImageD prev_color = with_variance(prev.illumination);
    ImageD prev_moments(kW, kH, 4);
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        const double l =
            0.2126 * prev_color.at(x, y, 0) + 0.7152 * prev_color.at(x, y, 1) + 0.0722 * prev_color.at(x, y, 2);
        prev_moments.at(x, y, 0) = l;
        prev_moments.at(x, y, 1) = 0;  // the standard deviation: four frames of the same light
        prev_moments.at(x, y, 2) = 4;
      }
    const ImageD illumination = to_image(cur.illumination), motion = to_image(cur.motion);
    ImageD integrated, moments;
    for (int frame = 0; frame < 2; ++frame) {
      RenderGraph g;
      const auto dn = g.add_image("depth_normal", kW, kH, F::RGBA16Uint, Lifetime::Persistent);
      const auto color = g.add_image("color_history", kW, kH, F::RGBA16F, Lifetime::Persistent);
      const auto mom = g.add_image("moments", kW, kH, F::R32Uint, Lifetime::Persistent);
      if (frame == 0) {
        harness.fill(g, dn, depth_normal_texels(prev_dn));
        harness.fill(g, color, prev_color);
        harness.fill(g, mom, moments_words(prev_moments));
      } else {
        harness.fill(g, dn, depth_normal_texels(dn_now));
        passes::TemporalResources res;
        res.illumination = harness.input(g, "illumination", illumination, F::RGBA32F);
        res.motion = harness.input(g, "motion", motion, F::RGBA32F);
        res.depth_normal = dn;
        res.color_history = color;
        res.moments = mom;
        res.integrated = g.add_image("integrated", kW, kH, F::RGBA16F);
        res.counters = counters.import(g);
        passes::add_temporal(g, pipelines, res, settings);
        harness.readback(g, res.integrated, &integrated);
        harness.readback(g, mom, &moments);
      }
      harness.run(g);
    }
    const ImageD q_prev_color = quantize(prev_color, F::RGBA16F);
    const ImageD q_prev_moments = moments_values(moments_words(prev_moments));
    ref::TemporalInputs in{&illumination, &motion, &dn_now, &prev_dn, &q_prev_color, &q_prev_moments, nullptr};
    const auto want =
        ref::temporal(in, {settings.alpha, settings.moments_alpha, settings.history_cap, true, settings.antilag});
    const double m = magnitude(illumination) + magnitude(prev_color);
    DENOISE_CHECK_CLOSE(compare(integrated, want.integrated, 3, [m](double v) { return fp16_ulp(v) + 1e-5 * m; }),
                        "temporal colour");
    DENOISE_CHECK_CLOSE(compare_moments(moments_values(moments), want.moments, m, m * m), "temporal moments");
    int kept = 0;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) kept += want.moments.at(x, y, 2) > 1.0;
    CHECK(kept > int(kW * kH) / 2);  // most pixels reproject: the camera moved a little
  }

  SUBCASE("atrous (B3 spline) at steps 1, 2 and 4") {
    passes::PipelineCache pipelines(*device);
    asvgf::DenoiseSettings settings;
    const ImageD dn = to_image(cur.depth_normal);
    const ImageD color = with_variance(cur.illumination);
    for (int iteration = 0; iteration < 3; ++iteration) {
      CAPTURE(iteration);
      GraphHarness harness(*device);
      RenderGraph g;
      const auto out = g.add_image("atrous_out", kW, kH, F::RGBA16F);
      passes::AtrousResources res{harness.input(g, "color_in", color, F::RGBA16F),
                                  harness.input(g, "depth_normal", depth_normal_texels(dn), F::RGBA16Uint), out,
                                  std::nullopt};
      passes::add_atrous(g, pipelines, res, iteration, settings);
      ImageD got;
      harness.readback(g, out, &got);
      harness.run(g);
      const ImageD want =
          ref::atrous(quantize(color, F::RGBA16F), quantize(dn, F::RGBA32F),
                      {1 << iteration, 0, settings.sigma_z, settings.sigma_n,
                       asvgf::luminance_sigma(settings, std::uint32_t(dn.width), std::uint32_t(dn.height))});
      const double m = magnitude(color);
      DENOISE_CHECK_CLOSE(compare(got, want, 4, [m](double v) { return fp16_ulp(v) + 1e-5 * m; }), "atrous");
    }
  }
}
