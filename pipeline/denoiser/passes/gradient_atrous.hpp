// denoiser/passes/gradient_atrous.hpp: the `gradient_atrous` pass (shaders/denoise/gradient_atrous.comp):
// one edge-aware a-trous iteration over (delta, Delta) at 1/3 resolution, step 2^iteration.
#pragma once

#include <optional>

#include "asvgf/compute_pass.hpp"
#include "asvgf/denoise_settings.hpp"
#include "asvgf/render_graph.hpp"

namespace asvgf::passes {

struct GradientAtrousResources {
  // read: 1/3 res RGBA16F (delta, Delta); with samples_in the gradient samples (gradient.hpp's
  // gradient_prev with l_cur in z), whose gradient the iteration computes as the gradient pass does.
  graph::ResourceId gradient_in = 0;
  graph::ResourceId depth_normal = 0;  // read unless strata_guide_in is given: full-res guide (RGBA16UI)
  graph::ResourceId gradient_out = 0;  // written: 1/3 res RGBA16F
  // 1/3 res RGBA16UI: depth_normal's texel at each stratum's centre pixel, the only texels an
  // iteration reads. The first of several iterations writes it; the others read it instead of
  // depth_normal.
  std::optional<graph::ResourceId> strata_guide_out;
  std::optional<graph::ResourceId> strata_guide_in;
  bool samples_in = false;          // iteration 0 only (step 1; not with strata_guide_in)
  bool luminance_in_alpha = false;  // samples_in: the samples come from pathtrace's split signals
};
// Adds "gradient_atrous.<iteration + 1>" with step 2^iteration (sigma_z, sigma_n from settings).
// Throws std::invalid_argument for both strata guides at once, one not of the gradient's size, or
// samples_in with strata_guide_in or past iteration 0.
graph::PassBuilder add_gradient_atrous(graph::RenderGraph& graph, PipelineCache& pipelines,
                                       const GradientAtrousResources& r, int iteration,
                                       const DenoiseSettings& settings);

}  // namespace asvgf::passes
