// denoiser/passes/variance.hpp: the `variance` pass (shaders/denoise/variance.comp): temporal variance from
// the moments, or a 7x7 spatial estimate while the history is shorter than settings.min_history.
#pragma once

#include <string>

#include "asvgf/compute_pass.hpp"
#include "asvgf/denoise_settings.hpp"
#include "asvgf/render_graph.hpp"

namespace asvgf::passes {

struct VarianceResources {
  graph::ResourceId integrated = 0;      // read: the temporal pass's R32Uint (RGB9E5 words)
  graph::ResourceId moments = 0;         // read: this frame's moments, R32Uint words (temporal.hpp)
  graph::ResourceId depth_normal = 0;    // read: RGBA16UI
  graph::ResourceId color_variance = 0;  // written: RGBA16F (rgb, variance)
  // read: what the signal is re-modulated by (the spatial estimate's scale): a float format, or
  // R32Uint RGB9E5 words (input_formats.hpp)
  graph::ResourceId albedo = 0;
  std::string prefix;  // of the pass name: "specular." for the second signal
};
// Adds "<prefix>variance". Throws std::invalid_argument where integrated or moments is not R32Uint.
graph::PassBuilder add_variance(graph::RenderGraph& graph, PipelineCache& pipelines, const VarianceResources& r,
                                const DenoiseSettings& settings);

}  // namespace asvgf::passes
