#include "passes/variance.hpp"

#include <cstddef>

#include "shaders/variance.hpp"

namespace asvgf::passes {
namespace {

struct Uniforms {
  std::uint32_t width, height;
  float sigma_z, sigma_n, sigma_l, min_history;
};
static_assert(sizeof(Uniforms) == 24);

}  // namespace

graph::PassBuilder add_variance(graph::RenderGraph& graph, PipelineCache& pipelines, const VarianceResources& r,
                                const DenoiseSettings& s) {
  const auto& decl = graph.resource(r.color_variance);
  const Uniforms u{decl.width, decl.height, s.sigma_z, s.sigma_n, s.sigma_l, s.min_history};
  const hal::ShaderInfo& shader = asvgf::shaders::variance;
  const auto pipeline = pipelines.get(shader, sizeof(Uniforms),
                                      {{"width", offsetof(Uniforms, width)},
                                       {"height", offsetof(Uniforms, height)},
                                       {"sigma_z", offsetof(Uniforms, sigma_z)},
                                       {"sigma_n", offsetof(Uniforms, sigma_n)},
                                       {"sigma_l", offsetof(Uniforms, sigma_l)},
                                       {"min_history", offsetof(Uniforms, min_history)}});
  return add_compute_pass(graph, "variance", shader, pipeline,
                          {{"integrated", r.integrated},
                           {"moments", r.moments},
                           {"depth_normal", r.depth_normal},
                           {"color_variance", r.color_variance}},
                          to_bytes(u), {u.width, u.height, 1});
}

}  // namespace asvgf::passes
