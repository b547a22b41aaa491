// The whole denoiser (gradient, gradient_atrous, temporal, variance, atrous, composite) as a small
// render graph on a device, fed from host images frame after frame; returns every output and
// history. Used by the stability tests (synthetic inputs; no path tracer needed). The chain is
// passes::add_denoiser, the same call the frame makes.
#pragma once

#include <optional>

#include "asvgf/denoiser_graph.hpp"
#include "pipeline/denoise_harness.hpp"

namespace denoise_test {

struct FrameInput {
  ImageD illumination;                  // 4 channels (rgb)
  ImageD depth_normal;                  // 4 channels
  ImageD motion;                        // 2 channels
  ImageD albedo;                        // 4 channels
  std::optional<ImageD> gradient_prev;  // 2 channels at 1/3 resolution; adaptive alpha when set
};

struct FrameOutput {
  ImageD hdr, display, color_history, moments, integrated, filtered;  // colour histories as values (rgb, 0)
  ImageD variance;  // the variance pass's output (rgb, variance), with ChainOptions::read_variance
};

struct ChainOptions {
  // RGBA16F, or R32Uint: FrameInput::albedo given as RGB9E5 words (shaders/common/albedo.glsl)
  hal::Format albedo_format = hal::Format::RGBA16F;
  // RG32F, or R32Uint: FrameInput::motion given as two halves a word (shaders/common/motion.glsl)
  hal::Format motion_format = hal::Format::RG32F;
  bool read_variance = false;  // run the variance pass (else left out: the first iteration estimates it)
};

class DenoiserChain {
 public:
  DenoiserChain(hal::Device& device, asvgf::DenoiseSettings settings, ChainOptions options = {})
      : settings_(settings), options_(options), pipelines_(device), harness_(device), counters_(device) {}

  asvgf::passes::SanitizeCounters& counters() { return counters_; }
  asvgf::DenoiseSettings& settings() { return settings_; }
  // A camera cut: no history is valid next frame.
  void reset_histories() { harness_.runtime().reset_histories(); }

  FrameOutput run(const FrameInput& in) {
    using hal::Format;
    const auto w = static_cast<std::uint32_t>(in.illumination.width),
               h = static_cast<std::uint32_t>(in.illumination.height);
    asvgf::graph::RenderGraph g;
    const auto dn = g.add_image("depth_normal", w, h, Format::RGBA16Uint, asvgf::graph::Lifetime::Persistent);
    harness_.fill(g, dn, depth_normal_texels(in.depth_normal));
    asvgf::passes::GraphDenoiserInputs d;
    d.illumination = harness_.input(g, "illumination", in.illumination, Format::RGBA32F);
    d.motion = options_.motion_format == Format::R32Uint
                   ? harness_.input(g, "motion", motion_half_words(in.motion), Format::R32Uint)
                   : harness_.input(g, "motion", in.motion, options_.motion_format);
    d.depth_normal = dn;
    d.albedo = options_.albedo_format == Format::R32Uint
                   ? harness_.input(g, "albedo", rgb9e5_words(in.albedo), Format::R32Uint)
                   : harness_.input(g, "albedo", in.albedo, options_.albedo_format);
    d.counters = counters_.import(g);
    d.hdr = g.add_image("hdr", w, h, Format::RGBA32F);
    d.display = g.add_image("display", w, h, Format::RGBA8Unorm);
    if (in.gradient_prev) d.gradient_prev = harness_.input(g, "gradient_prev", *in.gradient_prev, Format::RG32F);
    const bool spatial = settings_.atrous_iterations > 0;
    const auto out = asvgf::passes::add_denoiser(g, pipelines_, d, settings_, asvgf::DenoiseMethod::Asvgf);
    FrameOutput result;
    harness_.readback(g, d.hdr, &result.hdr);
    harness_.readback(g, d.display, &result.display);
    harness_.readback(g, *out.color_history, &result.color_history);
    harness_.readback(g, *out.moments, &result.moments);
    harness_.readback(g, out.filtered, &result.filtered);
    if (spatial) harness_.readback(g, *out.integrated, &result.integrated);
    if (spatial && options_.read_variance) harness_.readback(g, *out.variance, &result.variance);
    harness_.run(g);
    if (!spatial) result.integrated = result.filtered;
    // A spatial chain keeps its colour history and temporal result as RGB9E5 words: their values.
    if (g.resource(*out.color_history).format == Format::R32Uint)
      result.color_history = rgb9e5_values(result.color_history);
    if (spatial && g.resource(*out.integrated).format == Format::R32Uint)
      result.integrated = rgb9e5_values(result.integrated);
    result.moments = moments_values(result.moments);  // pack_moments's words
    return result;
  }

 private:
  asvgf::DenoiseSettings settings_;
  ChainOptions options_;
  asvgf::passes::PipelineCache pipelines_;
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
