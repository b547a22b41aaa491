#include "passes/gradient_atrous.hpp"

#include <cstddef>

#include "graph/graph_runtime.hpp"
#include "passes/compute_pass.hpp"
#include "shaders/gradient_atrous.hpp"

namespace asvgf::passes {
namespace {

struct Uniforms {
  std::uint32_t width, height, gradient_width, gradient_height;
  std::int32_t step;
  float sigma_z, sigma_n;
};
static_assert(sizeof(Uniforms) == 28);

}  // namespace

GradientAtrousPass::GradientAtrousPass(hal::Device& device) : device_(device) {
  const hal::ShaderInfo& shader = asvgf::shaders::gradient_atrous;
  check_uniform_layout(shader, sizeof(Uniforms),
                       {{"width", offsetof(Uniforms, width)},
                        {"height", offsetof(Uniforms, height)},
                        {"gradient_width", offsetof(Uniforms, gradient_width)},
                        {"gradient_height", offsetof(Uniforms, gradient_height)},
                        {"step", offsetof(Uniforms, step)},
                        {"sigma_z", offsetof(Uniforms, sigma_z)},
                        {"sigma_n", offsetof(Uniforms, sigma_n)}});
  pipeline_ = device_.create_pipeline({"gradient_atrous", &shader, {}});
}

GradientAtrousPass::~GradientAtrousPass() { device_.destroy(pipeline_); }

graph::PassBuilder GradientAtrousPass::add(graph::RenderGraph& graph, const Resources& r, int iteration,
                                           const DenoiseSettings& s) const {
  const auto& full = graph.resource(r.depth_normal);
  const auto& out = graph.resource(r.gradient_out);
  const Uniforms u{full.width, full.height, out.width, out.height, 1 << iteration, s.sigma_z, s.sigma_n};
  const hal::ShaderInfo& shader = asvgf::shaders::gradient_atrous;
  return add_compute_pass(graph, "gradient_atrous." + std::to_string(iteration + 1), shader, pipeline_,
                   {{"gradient_in", r.gradient_in}, {"depth_normal", r.depth_normal},
                    {"gradient_out", r.gradient_out}},
                   to_bytes(u),
                   {u.gradient_width, u.gradient_height, 1});
}

graph::ResourceId GradientAtrousPass::add_iterations(graph::RenderGraph& graph, graph::ResourceId gradient,
                                                     graph::ResourceId depth_normal, const DenoiseSettings& s) const {
  graph::ResourceId current = gradient;
  const auto& decl = graph.resource(gradient);
  const std::uint32_t w = decl.width, h = decl.height;
  for (int i = 0; i < s.gradient_iterations; ++i) {
    const graph::ResourceId next = graph.add_image("gradient." + std::to_string(i + 1), w, h, hal::Format::RGBA16F);
    add(graph, {current, depth_normal, next}, i, s);
    current = next;
  }
  return current;
}

}  // namespace asvgf::passes
