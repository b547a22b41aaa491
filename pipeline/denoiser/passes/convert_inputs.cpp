#include "denoiser/passes/convert_inputs.hpp"

#include "shaders/convert_inputs.hpp"

namespace asvgf::passes {

graph::PassBuilder add_convert_inputs(graph::RenderGraph& graph, PipelineCache& pipelines,
                                      const ConvertInputsResources& r, const ConvertInputsParams& p) {
  using Uniforms = asvgf::shaders::convert_inputs_uniforms::Params;
  const auto& decl = graph.resource(r.illumination);
  Uniforms u{};
  u.width = decl.width;
  u.height = decl.height;
  u.color_is_radiance = p.color_is_radiance ? 1u : 0u;
  u.motion_scale_x = p.motion_scale_x;
  u.motion_scale_y = p.motion_scale_y;
  const hal::ShaderInfo& shader = asvgf::shaders::convert_inputs;
  return add_compute_pass(graph, "convert_inputs", shader, pipelines.get<Uniforms>(shader),
                          {{"color", r.color},
                           {"albedo", r.albedo},
                           {"motion", r.motion},
                           {"illumination", r.illumination},
                           {"modulation", r.modulation},
                           {"motion_out", r.motion_out}},
                          to_bytes(u), {u.width, u.height, 1});
}

}  // namespace asvgf::passes
