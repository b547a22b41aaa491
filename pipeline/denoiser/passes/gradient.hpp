// denoiser/passes/gradient.hpp: the `gradient` pass (shaders/denoise/gradient.comp): per 3x3 stratum,
// delta = l_cur - l_prev and Delta = max(l_cur, l_prev) of the forward-projected sample; and
// `gradient_reprojected`, the same estimated from reprojected noisy luminance.
#pragma once

#include "asvgf/compute_pass.hpp"
#include "asvgf/render_graph.hpp"

namespace asvgf::passes {

struct GradientResources {
  // w x h, this frame's demodulated samples: read where they hold the re-shaded samples (not
  // current_given); with current_given only its size is used.
  graph::ResourceId illumination = 0;
  graph::ResourceId gradient_prev = 0;  // read: ceil(w/3) x ceil(h/3) (l_prev, index or -1[, l_cur])
  graph::ResourceId gradient = 0;       // written: ceil(w/3) x ceil(h/3) RGBA16F (delta, Delta, 0, 0)
  bool luminance_in_alpha = false;      // illumination.a holds the luminance (pathtrace's split signals)
  bool current_given = false;           // gradient_prev.z holds l_cur (GraphDenoiserInputs::gradient_current_given)
};
// Adds the pass "gradient".
graph::PassBuilder add_gradient(graph::RenderGraph& graph, PipelineCache& pipelines, const GradientResources& r);

// The gradient without re-shaded samples (shaders/denoise/gradient_reprojected.comp): this frame's
// noisy luminance against last frame's, reprojected, summed per stratum.
struct ReprojectedGradientResources {
  graph::ResourceId illumination = 0;  // read: w x h, this frame's demodulated samples
  graph::ResourceId motion = 0;        // read: previous minus current pixel position
  graph::ResourceId depth_normal = 0;  // read, and its history read: persistent RGBA16UI
  graph::ResourceId luminance = 0;     // written, and its history read: persistent w x h R32F
  graph::ResourceId gradient = 0;      // written: ceil(w/3) x ceil(h/3) RGBA16F (delta, Delta, 0, 0)
};
// Adds the pass "gradient_reprojected".
graph::PassBuilder add_gradient_reprojected(graph::RenderGraph& graph, PipelineCache& pipelines,
                                            const ReprojectedGradientResources& r);

}  // namespace asvgf::passes
