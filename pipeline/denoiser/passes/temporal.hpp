// denoiser/passes/temporal.hpp: the `temporal` pass (shaders/denoise/temporal.comp): sanitises this frame's
// samples (NaN/Inf dropped and counted), reprojects last frame's colour and moments, blends them
// with a constant or (with a gradient) adaptive alpha, and tracks the history length.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "asvgf/compute_pass.hpp"
#include "asvgf/denoise_settings.hpp"
#include "asvgf/render_graph.hpp"

namespace asvgf::passes {

struct TemporalResources {
  graph::ResourceId illumination = 0;  // read: RGBA32F demodulated samples of this frame
  graph::ResourceId motion = 0;        // read: RG32F, previous minus current pixel position
  graph::ResourceId depth_normal = 0;  // read, and its history read: persistent RGBA16UI
  // Its history read: persistent, RGBA16F (rgb, variance) or R32Uint (RGB9E5 words, a spatial chain's).
  graph::ResourceId color_history = 0;
  // History read and written: persistent R32Uint, E[l], sqrt(Var[l]) and n in one word
  // (shaders/common/denoise.glsl: pack_moments).
  graph::ResourceId moments = 0;
  // Written, in color_history's format: RGBA16F (rgb, temporal variance) or RGB9E5 words (rgb); may be
  // color_history.
  graph::ResourceId integrated = 0;
  graph::ResourceId counters = 0;             // read-written SanitizeCounters buffer
  std::optional<graph::ResourceId> gradient;  // read: 1/3 res RGBA16F (delta^, Delta^); adaptive alpha
  std::string prefix;                         // of the pass name: "specular." for the second signal
  bool virtual_motion = false;  // `motion` goes through reflections: loose depth test (specular_motion.comp)
};
// Adds "<prefix>temporal". The adaptive variant is used when a gradient is given. Throws
// std::invalid_argument where color_history and integrated are not both RGBA16F or both R32Uint, or
// the moments are not R32Uint.
// Histories not valid this frame (first frame, GraphRuntime::reset_histories) reset every pixel.
graph::PassBuilder add_temporal(graph::RenderGraph& graph, PipelineCache& pipelines, const TemporalResources& r,
                                const DenoiseSettings& settings);

// Throws std::invalid_argument, naming `pass` and the image, unless `moments` is R32Uint: the words
// the temporal pass writes, which the passes that read them check too.
void require_moments_words(const graph::RenderGraph& graph, graph::ResourceId moments, const std::string& pass);

}  // namespace asvgf::passes
