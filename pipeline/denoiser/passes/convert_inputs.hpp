// denoiser/passes/convert_inputs.hpp: the `convert_inputs` pass (shaders/denoise/convert_inputs.comp): a
// renderer's radiance and motion vectors in its own conventions as the denoiser's demodulated
// illumination, re-modulation albedo and motion (previous minus current, pixels, y down).
#pragma once

#include "asvgf/compute_pass.hpp"
#include "asvgf/render_graph.hpp"

namespace asvgf::passes {

struct ConvertInputsResources {
  graph::ResourceId color = 0, albedo = 0, motion = 0;                 // read
  graph::ResourceId illumination = 0, modulation = 0, motion_out = 0;  // written (RGBA32F, R32Uint, RGBA32F)
};
struct ConvertInputsParams {
  bool color_is_radiance = true;
  float motion_scale_x = 1.0f, motion_scale_y = 1.0f;  // asvgf::motion_scale
};
graph::PassBuilder add_convert_inputs(graph::RenderGraph& graph, PipelineCache& pipelines,
                                      const ConvertInputsResources& r, const ConvertInputsParams& p);

}  // namespace asvgf::passes
