// The whole denoiser (gradient, gradient_atrous, temporal, variance, atrous, composite) as a small
// render graph on a device, fed from host images frame after frame; returns every output and
// history. Used by the stability tests (synthetic inputs; no path tracer needed).
#pragma once

#include <optional>

#include "passes/atrous.hpp"
#include "passes/composite.hpp"
#include "passes/gradient.hpp"
#include "passes/gradient_atrous.hpp"
#include "passes/temporal.hpp"
#include "passes/variance.hpp"
#include "pipeline/denoise_harness.hpp"

namespace denoise_test {

struct FrameInput {
  ImageD illumination;  // 4 channels (rgb)
  ImageD depth_normal;  // 4 channels
  ImageD motion;        // 2 channels
  ImageD albedo;        // 4 channels
  std::optional<ImageD> gradient_prev;  // 2 channels at 1/3 resolution; adaptive alpha when set
};

struct FrameOutput {
  ImageD hdr, display, color_history, moments, integrated, filtered;
};

class DenoiserChain {
 public:
  DenoiserChain(hal::Device& device, asvgf::passes::DenoiseSettings settings)
      : settings_(settings), gradient_(device), gradient_atrous_(device), temporal_(device), variance_(device),
        atrous_(device), composite_(device), harness_(device), counters_(device) {}

  asvgf::passes::SanitizeCounters& counters() { return counters_; }
  asvgf::passes::DenoiseSettings& settings() { return settings_; }
  // A camera cut: no history is valid next frame.
  void reset_histories() { harness_.runtime().reset_histories(); }

  FrameOutput run(const FrameInput& in) {
    using hal::Format;
    using asvgf::graph::Lifetime;
    const auto w = static_cast<std::uint32_t>(in.illumination.width), h = static_cast<std::uint32_t>(in.illumination.height);
    asvgf::graph::RenderGraph g;
    const auto dn = g.add_image("depth_normal", w, h, Format::RGBA32F, Lifetime::Persistent);
    harness_.fill(g, dn, in.depth_normal);
    const auto color_history = g.add_image("color_history", w, h, Format::RGBA16F, Lifetime::Persistent);
    const auto moments = g.add_image("moments", w, h, Format::RGBA32F, Lifetime::Persistent);
    asvgf::passes::TemporalPass::Resources t;
    t.illumination = harness_.input(g, "illumination", in.illumination, Format::RGBA32F);
    t.motion = harness_.input(g, "motion", in.motion, Format::RG32F);
    t.depth_normal = dn;
    t.color_history = color_history;
    t.moments = moments;
    t.counters = counters_.import(g);
    if (in.gradient_prev && settings_.adaptive) {
      const auto gp = harness_.input(g, "gradient_prev", *in.gradient_prev, Format::RG32F);
      const auto grad = g.add_image("gradient", (w + 2) / 3, (h + 2) / 3, Format::RGBA16F);
      gradient_.add(g, {t.illumination, gp, grad});
      t.gradient = gradient_atrous_.add_iterations(g, grad, dn, settings_);
    }
    const bool spatial = settings_.atrous_iterations > 0;
    t.integrated = spatial ? g.add_image("integrated", w, h, Format::RGBA16F) : color_history;
    temporal_.add(g, t, settings_);
    asvgf::graph::ResourceId filtered = t.integrated;
    if (spatial) {
      const auto cv = g.add_image("color_variance", w, h, Format::RGBA16F);
      variance_.add(g, {t.integrated, moments, dn, cv}, settings_);
      filtered = atrous_.add_iterations(g, cv, dn, color_history, settings_);
    }
    const auto hdr = g.add_image("hdr", w, h, Format::RGBA32F);
    const auto display = g.add_image("display", w, h, Format::RGBA8Unorm);
    composite_.add(g, {filtered, harness_.input(g, "albedo", in.albedo, Format::RGBA16F), hdr, display, t.counters},
                   settings_);
    FrameOutput out;
    harness_.readback(g, hdr, &out.hdr);
    harness_.readback(g, display, &out.display);
    harness_.readback(g, color_history, &out.color_history);
    harness_.readback(g, moments, &out.moments);
    harness_.readback(g, filtered, &out.filtered);
    if (spatial) harness_.readback(g, t.integrated, &out.integrated);
    harness_.run(g);
    if (!spatial) out.integrated = out.filtered;
    return out;
  }

 private:
  asvgf::passes::DenoiseSettings settings_;
  asvgf::passes::GradientPass gradient_;
  asvgf::passes::GradientAtrousPass gradient_atrous_;
  asvgf::passes::TemporalPass temporal_;
  asvgf::passes::VariancePass variance_;
  asvgf::passes::AtrousPass atrous_;
  asvgf::passes::CompositePass composite_;
  GraphHarness harness_;
  asvgf::passes::SanitizeCounters counters_;
};

// A flat wall facing the camera at depth z (zero depth gradient, normal towards the camera), still
// camera (zero motion), white albedo, constant illumination `value`.
inline FrameInput flat_frame(int w, int h, double value, double z = 4.0) {
  FrameInput f{ImageD(w, h, 4), ImageD(w, h, 4), ImageD(w, h, 2), ImageD(w, h, 4, 1.0), std::nullopt};
  const auto e = asvgf::reference::oct_encode<float>({0.0f, 0.0f, -1.0f});
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      for (int c = 0; c < 3; ++c) f.illumination.at(x, y, c) = value;
      f.depth_normal.at(x, y, 0) = z;
      f.depth_normal.at(x, y, 2) = e[0];
      f.depth_normal.at(x, y, 3) = e[1];
    }
  return f;
}

}  // namespace denoise_test
