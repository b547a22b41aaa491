// asvgf/denoiser_graph.hpp: the denoiser recorded into your own render graph (asvgf/render_graph.hpp),
// for renderers that schedule their passes in it: the denoiser's transient images then share memory
// with yours, and it reads your G-buffer in its packed layout without a conversion pass.
// asvgf::Denoiser (asvgf/denoiser.hpp) is this call over imported images; our renderer
// (pipeline/renderer/frame_graph.cpp) and the tests use it directly.
//
// One call declares A-SVGF's gradient reconstruction (gradient, gradient_atrous x
// settings.gradient_iterations), temporal accumulation, variance, the a-trous iterations and
// composite over images the caller declared in the graph.
#pragma once

#include <optional>
#include <string>

#include "asvgf/compute_pass.hpp"
#include "asvgf/denoise_settings.hpp"
#include "asvgf/render_graph.hpp"
#include "asvgf/sanitize_counters.hpp"

namespace asvgf::passes {

struct GraphDenoiserInputs {
  // read: demodulated radiance of this frame, any float format with rgb (our renderer: RGBA16F,
  // finite samples clamped to 65504; the temporal pass clamps there anyway)
  graph::ResourceId illumination = 0;
  // read: xy = previous minus current pixel position, in any float format, or R32UI with x and y as
  // packHalf2x16's halves (4 bytes a pixel; our renderer's: shaders/common/motion.glsl)
  graph::ResourceId motion = 0;
  // read, and its history: persistent RGBA16UI, the packed surface (shaders/common/depth_normal.glsl):
  // linear view depth, its gradient max(|dz/dx|, |dz/dy|) and the octahedral-encoded unit normal
  // in 8 bytes; all 0 on background (a depth not finite, <= 0 or >= kBackgroundDepth:
  // asvgf::is_background_depth).
  graph::ResourceId depth_normal = 0;
  // read: what composite re-modulates by; also the short-history variance estimate's scale (it
  // compares radiance, the neighbours re-modulated by the pixel's albedo). Any float format, or
  // R32UI RGB9E5 words (Vulkan's E5B9G9R9 layout: 4 bytes a pixel, but every channel gets the
  // largest one's step, 2^-9 to 2^-8 of it, so a dark channel beside a bright one rounds by much of
  // itself, to 0 below about 1/512 of it: divide your radiance by the word's value, as our renderer
  // does; shaders/common/albedo.glsl).
  graph::ResourceId albedo = 0;
  graph::ResourceId counters = 0;  // SanitizeCounters::import of this graph
  graph::ResourceId hdr = 0;       // written by composite: RGBA32F or RGBA16F linear radiance
  graph::ResourceId display = 0;   // written by composite: RGBA8 tonemapped sRGB
  // A-SVGF with GradientSource::Reshaded: the gradient samples (asvgf/denoiser.hpp's table), one a
  // 3x3 stratum (ceil(w/3) x ceil(h/3), RGBA32F): x last frame's luminance forward-projected into
  // this frame, y the sample's pixel in the stratum (-1: none), and with gradient_current_given z
  // this frame's luminance of the re-shaded sample. Absent: constant alpha. With
  // GradientSource::Reprojected the chain estimates the gradient itself (gradient_reprojected) and
  // ignores this and the skip reason.
  std::optional<graph::ResourceId> gradient_prev;
  // Not empty: the gradient passes are declared but left out for this reason (nothing moved), and
  // the temporal pass uses constant alpha this frame.
  std::string gradient_skip_reason;
  // true: gradient_prev.z holds this frame's luminance of each re-shaded sample, shaded apart from
  // `illumination` (our renderer's pathtrace_carried); false: the sample's pixel of `illumination`
  // is the re-shaded sample.
  bool gradient_current_given = false;
  // Two signals (pathtrace's SPLIT_SPECULAR, scenes with glossy materials): `illumination` is the
  // diffuse one, with the one-signal luminance in .a for the gradient, and `specular` (RGBA32F,
  // divided by `specular_albedo`, RGBA16F) gets a chain of its own: passes and histories named
  // "specular.*", the same gradient; composite adds it re-modulated. `specular_albedo` is required
  // with `specular` (add_denoiser throws std::invalid_argument without it).
  std::optional<graph::ResourceId> specular, specular_albedo;
  // With `specular`: its history's motion through the reflection's virtual point (specular_motion), a
  // float format (z = 1 where the history moved through the reflection); absent, the specular history
  // follows `motion`.
  std::optional<graph::ResourceId> specular_motion;
};

struct GraphDenoiserOutputs {
  graph::ResourceId filtered = 0;  // what composite modulated: the last a-trous output, the EMA, or the input
  std::optional<graph::ResourceId> gradient;  // reconstructed (delta^, Delta^), when the gradient passes run
  // Persistent R32Uint: E[l], sqrt(Var[l]) and n in one word (shaders/common/denoise.glsl: pack_moments).
  std::optional<graph::ResourceId> moments;
  // The temporal pass's output and the persistent colour history: with a-trous iterations R32Uint,
  // RGB9E5 words (rgb: Vulkan's E5B9G9R9 layout); the EMA's RGBA16F (rgb, temporal variance).
  std::optional<graph::ResourceId> integrated;
  std::optional<graph::ResourceId> variance;  // the variance pass's output (RGBA16F), else `integrated`
  std::optional<graph::ResourceId> color_history;
  std::optional<graph::ResourceId> specular;  // the specular chain's `filtered`, with two signals
};

// `method` nothing: no filter, composite shows the illumination as it is (raw samples, an
// accumulation). Ema: temporal accumulation at constant alpha; Svgf: + variance and the a-trous
// iterations; Asvgf: + the gradient's adaptive alpha (gradient_prev, or GradientSource::Reprojected).
GraphDenoiserOutputs add_denoiser(graph::RenderGraph& graph, PipelineCache& pipelines, const GraphDenoiserInputs& in,
                                  const DenoiseSettings& settings, std::optional<DenoiseMethod> method);

}  // namespace asvgf::passes
