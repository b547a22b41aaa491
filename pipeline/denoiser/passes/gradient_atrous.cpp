#include "denoiser/passes/gradient_atrous.hpp"

#include <cstddef>
#include <string>

#include "shaders/gradient_atrous.hpp"

namespace asvgf::passes {
namespace {

// The shader's uniform block, as the shader tool generated it.
using Uniforms = asvgf::shaders::gradient_atrous_uniforms::Params;

}  // namespace

graph::PassBuilder add_gradient_atrous(graph::RenderGraph& graph, PipelineCache& pipelines,
                                       const GradientAtrousResources& r, int iteration, const DenoiseSettings& s) {
  const auto& full = graph.resource(r.depth_normal);
  const auto& out = graph.resource(r.gradient_out);
  const Uniforms u{full.width, full.height, out.width, out.height, 1 << iteration, s.sigma_z, s.sigma_n};
  const hal::ShaderInfo& shader = asvgf::shaders::gradient_atrous;
  const auto pipeline = pipelines.get<Uniforms>(shader);
  return add_compute_pass(
      graph, "gradient_atrous." + std::to_string(iteration + 1), shader, pipeline,
      {{"gradient_in", r.gradient_in}, {"depth_normal", r.depth_normal}, {"gradient_out", r.gradient_out}}, to_bytes(u),
      {u.gradient_width, u.gradient_height, 1});
}

}  // namespace asvgf::passes
