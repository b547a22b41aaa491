#include "passes/variance.hpp"

#include <cstddef>

#include "graph/graph_runtime.hpp"
#include "passes/compute_pass.hpp"
#include "shaders/variance.hpp"

namespace asvgf::passes {
namespace {

struct Uniforms {
  std::uint32_t width, height;
  float sigma_z, sigma_n, sigma_l, min_history;
};
static_assert(sizeof(Uniforms) == 24);

}  // namespace

VariancePass::VariancePass(hal::Device& device) : device_(device) {
  const hal::ShaderInfo& shader = asvgf::shaders::variance;
  check_uniform_layout(shader, sizeof(Uniforms),
                       {{"width", offsetof(Uniforms, width)},
                        {"height", offsetof(Uniforms, height)},
                        {"sigma_z", offsetof(Uniforms, sigma_z)},
                        {"sigma_n", offsetof(Uniforms, sigma_n)},
                        {"sigma_l", offsetof(Uniforms, sigma_l)},
                        {"min_history", offsetof(Uniforms, min_history)}});
  pipeline_ = device_.create_pipeline({"variance", &shader, {}});
}

VariancePass::~VariancePass() { device_.destroy(pipeline_); }

void VariancePass::add(graph::RenderGraph& graph, const Resources& r, const DenoiseSettings& s) const {
  const auto& decl = graph.resource(r.color_variance);
  const Uniforms u{decl.width, decl.height, s.sigma_z, s.sigma_n, s.sigma_l, s.min_history};
  const hal::ShaderInfo& shader = asvgf::shaders::variance;
  add_compute_pass(graph, "variance", shader, pipeline_,
                   {{"integrated", r.integrated},
                    {"moments", r.moments},
                    {"depth_normal", r.depth_normal},
                    {"color_variance", r.color_variance}},
                   to_bytes(u), {u.width, u.height, 1});
}

}  // namespace asvgf::passes
