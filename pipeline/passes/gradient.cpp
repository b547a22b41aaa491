#include "passes/gradient.hpp"

#include <cstddef>

#include "graph/graph_runtime.hpp"
#include "passes/compute_pass.hpp"
#include "shaders/gradient.hpp"

namespace asvgf::passes {
namespace {

struct Uniforms {
  std::uint32_t width, height, gradient_width, gradient_height;
};
static_assert(sizeof(Uniforms) == 16);

}  // namespace

GradientPass::GradientPass(hal::Device& device) : device_(device) {
  const hal::ShaderInfo& shader = asvgf::shaders::gradient;
  check_uniform_layout(shader, sizeof(Uniforms),
                       {{"width", offsetof(Uniforms, width)},
                        {"height", offsetof(Uniforms, height)},
                        {"gradient_width", offsetof(Uniforms, gradient_width)},
                        {"gradient_height", offsetof(Uniforms, gradient_height)}});
  pipeline_ = device_.create_pipeline({"gradient", &shader, {}});
}

GradientPass::~GradientPass() { device_.destroy(pipeline_); }

graph::PassBuilder GradientPass::add(graph::RenderGraph& graph, const Resources& r) const {
  const auto& full = graph.resource(r.illumination);
  const auto& out = graph.resource(r.gradient);
  const Uniforms u{full.width, full.height, out.width, out.height};
  const hal::ShaderInfo& shader = asvgf::shaders::gradient;
  return add_compute_pass(graph, "gradient", shader, pipeline_,
                   {{"illumination", r.illumination}, {"gradient_prev", r.gradient_prev},
                    {"gradient", r.gradient}},
                   to_bytes(u),
                   {u.gradient_width, u.gradient_height, 1});
}

}  // namespace asvgf::passes
