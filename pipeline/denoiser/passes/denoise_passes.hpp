// denoiser/passes/denoise_passes.hpp: the whole denoiser as one call, used by the frame (renderer/frame_graph.cpp),
// the tests and, later, the public API: A-SVGF's gradient reconstruction (gradient, gradient_atrous
// x settings.gradient_iterations), temporal accumulation, variance, the a-trous iterations and
// composite, over images the caller declared in the graph.
#pragma once

#include <optional>
#include <string>

#include "denoiser/graph/render_graph.hpp"
#include "denoiser/passes/compute_pass.hpp"
#include "denoiser/passes/denoise_settings.hpp"

namespace asvgf::passes {

// How much of the chain runs: None composites the input as it is (raw samples, an accumulation);
// Temporal is an exponential moving average (EMA); Spatiotemporal adds variance and the a-trous
// iterations (SVGF; with a gradient and settings.adaptive, A-SVGF).
enum class Filter { None, Temporal, Spatiotemporal };

struct DenoiserInputs {
  graph::ResourceId illumination = 0;  // read: RGBA32F demodulated radiance of this frame
  graph::ResourceId motion = 0;        // read: RGBA32F, xy = previous minus current pixel position
  graph::ResourceId depth_normal = 0;  // read, and its history: persistent RGBA32F (see common/denoise.glsl)
  graph::ResourceId albedo = 0;        // read: RGBA16F, what composite re-modulates by
  graph::ResourceId counters = 0;      // SanitizeCounters::import of this graph
  graph::ResourceId hdr = 0;           // written by composite: RGBA32F linear radiance
  graph::ResourceId display = 0;       // written by composite: RGBA8 tonemapped sRGB
  // A-SVGF with GradientSource::Reshaded: last frame's luminance forward-projected into this
  // frame's 3x3 strata (ceil(w/3) x ceil(h/3), RGBA32F, xy used; gradient_select/gradient_resolve
  // write it). Absent: constant alpha. With GradientSource::Reprojected the chain estimates the
  // gradient itself (gradient_reprojected) and ignores this and the skip reason.
  std::optional<graph::ResourceId> gradient_prev;
  // Not empty: the gradient passes are declared but left out for this reason (nothing moved), and
  // the temporal pass uses constant alpha this frame.
  std::string gradient_skip_reason;
  // Two signals (pathtrace's SPLIT_SPECULAR, scenes with glossy materials): `illumination` is the
  // diffuse one, with the one-signal luminance in .a for the gradient, and `specular` (RGBA32F,
  // divided by `specular_albedo`, RGBA16F) gets a chain of its own: passes and histories named
  // "specular.*", the same gradient; composite adds it re-modulated.
  std::optional<graph::ResourceId> specular, specular_albedo;
  // With `specular`: its history's motion through the reflection's virtual point (specular_motion);
  // absent, the specular history follows `motion`.
  std::optional<graph::ResourceId> specular_motion;
};

struct DenoiserOutputs {
  graph::ResourceId filtered = 0;  // what composite modulated: the last a-trous output, the EMA, or the input
  std::optional<graph::ResourceId> gradient;       // reconstructed (delta^, Delta^), when the gradient passes run
  std::optional<graph::ResourceId> moments;        // persistent (E[l], E[l^2], n)
  std::optional<graph::ResourceId> integrated;     // the temporal pass's output (rgb, temporal variance)
  std::optional<graph::ResourceId> variance;       // the variance pass's output, else `integrated`
  std::optional<graph::ResourceId> color_history;  // persistent colour history
  std::optional<graph::ResourceId> specular;       // the specular chain's `filtered`, with two signals
};

DenoiserOutputs add_denoiser(graph::RenderGraph& graph, PipelineCache& pipelines, const DenoiserInputs& in,
                             const DenoiseSettings& settings, Filter filter);

}  // namespace asvgf::passes
