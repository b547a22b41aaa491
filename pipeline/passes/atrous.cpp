#include "passes/atrous.hpp"

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "shaders/atrous.history.hpp"
#include "shaders/atrous.plain.hpp"

namespace asvgf::passes {
namespace {

struct Uniforms {
  std::uint32_t width, height;
  std::int32_t step;
  std::uint32_t kernel;
  float sigma_z, sigma_n, sigma_l;
};
static_assert(sizeof(Uniforms) == 28);

}  // namespace

graph::PassBuilder add_atrous(graph::RenderGraph& graph, PipelineCache& pipelines, const AtrousResources& r,
                              int iteration, const DenoiseSettings& s) {
  const auto& decl = graph.resource(r.color_out);
  const Uniforms u{decl.width, decl.height, 1 << iteration, static_cast<std::uint32_t>(s.kernel),
                   s.sigma_z,  s.sigma_n,   s.sigma_l};
  std::vector<Binding> bindings{{"color_in", r.color_in}, {"depth_normal", r.depth_normal}, {"color_out", r.color_out}};
  if (r.color_history) bindings.push_back({"color_history", *r.color_history});
  const hal::ShaderInfo& shader = r.color_history ? asvgf::shaders::atrous_history : asvgf::shaders::atrous_plain;
  const auto pipeline = pipelines.get(shader, sizeof(Uniforms),
                                      {{"width", offsetof(Uniforms, width)},
                                       {"height", offsetof(Uniforms, height)},
                                       {"step", offsetof(Uniforms, step)},
                                       {"kernel", offsetof(Uniforms, kernel)},
                                       {"sigma_z", offsetof(Uniforms, sigma_z)},
                                       {"sigma_n", offsetof(Uniforms, sigma_n)},
                                       {"sigma_l", offsetof(Uniforms, sigma_l)}});
  return add_compute_pass(graph, "atrous." + std::to_string(iteration + 1), shader, pipeline, std::move(bindings),
                          to_bytes(u), {u.width, u.height, 1});
}

}  // namespace asvgf::passes
