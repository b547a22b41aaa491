#include "passes/gradient.hpp"

#include <cstddef>

#include "shaders/gradient.hpp"

namespace asvgf::passes {
namespace {

struct Uniforms {
  std::uint32_t width, height, gradient_width, gradient_height;
};
static_assert(sizeof(Uniforms) == 16);

}  // namespace

graph::PassBuilder add_gradient(graph::RenderGraph& graph, PipelineCache& pipelines, const GradientResources& r) {
  const auto& full = graph.resource(r.illumination);
  const auto& out = graph.resource(r.gradient);
  const Uniforms u{full.width, full.height, out.width, out.height};
  const hal::ShaderInfo& shader = asvgf::shaders::gradient;
  const auto pipeline = pipelines.get(shader, sizeof(Uniforms),
                                      {{"width", offsetof(Uniforms, width)},
                                       {"height", offsetof(Uniforms, height)},
                                       {"gradient_width", offsetof(Uniforms, gradient_width)},
                                       {"gradient_height", offsetof(Uniforms, gradient_height)}});
  return add_compute_pass(
      graph, "gradient", shader, pipeline,
      {{"illumination", r.illumination}, {"gradient_prev", r.gradient_prev}, {"gradient", r.gradient}}, to_bytes(u),
      {u.gradient_width, u.gradient_height, 1});
}

}  // namespace asvgf::passes
