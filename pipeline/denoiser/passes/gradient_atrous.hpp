// denoiser/passes/gradient_atrous.hpp: the `gradient_atrous` pass (shaders/denoise/gradient_atrous.comp):
// one edge-aware a-trous iteration over (delta, Delta) at 1/3 resolution, step 2^iteration.
#pragma once

#include "asvgf/compute_pass.hpp"
#include "asvgf/denoise_settings.hpp"
#include "asvgf/render_graph.hpp"

namespace asvgf::passes {

struct GradientAtrousResources {
  graph::ResourceId gradient_in = 0;   // read: 1/3 res RGBA16F (delta, Delta)
  graph::ResourceId depth_normal = 0;  // read: full-res guide (RGBA32F)
  graph::ResourceId gradient_out = 0;  // written: 1/3 res RGBA16F
};
// Adds "gradient_atrous.<iteration + 1>" with step 2^iteration (sigma_z, sigma_n from settings).
graph::PassBuilder add_gradient_atrous(graph::RenderGraph& graph, PipelineCache& pipelines,
                                       const GradientAtrousResources& r, int iteration,
                                       const DenoiseSettings& settings);

}  // namespace asvgf::passes
