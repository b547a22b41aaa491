#include "passes/gradient.hpp"

#include <cstddef>

#include "shaders/gradient.hpp"

namespace asvgf::passes {
namespace {

// The shader's uniform block, as the shader tool generated it.
using Uniforms = asvgf::shaders::gradient_uniforms::Params;

}  // namespace

graph::PassBuilder add_gradient(graph::RenderGraph& graph, PipelineCache& pipelines, const GradientResources& r) {
  const auto& full = graph.resource(r.illumination);
  const auto& out = graph.resource(r.gradient);
  const Uniforms u{full.width, full.height, out.width, out.height};
  const hal::ShaderInfo& shader = asvgf::shaders::gradient;
  const auto pipeline = pipelines.get<Uniforms>(shader);
  return add_compute_pass(
      graph, "gradient", shader, pipeline,
      {{"illumination", r.illumination}, {"gradient_prev", r.gradient_prev}, {"gradient", r.gradient}}, to_bytes(u),
      {u.gradient_width, u.gradient_height, 1});
}

}  // namespace asvgf::passes
