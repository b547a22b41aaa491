#include "passes/atrous.hpp"

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "shaders/atrous.history.hpp"
#include "shaders/atrous.plain.hpp"

namespace asvgf::passes {
namespace {

// The uniform block as the shader tool generated it (every variant has the same block).
using Uniforms = asvgf::shaders::atrous_plain_uniforms::Params;

}  // namespace

graph::PassBuilder add_atrous(graph::RenderGraph& graph, PipelineCache& pipelines, const AtrousResources& r,
                              int iteration, const DenoiseSettings& s) {
  const auto& decl = graph.resource(r.color_out);
  const Uniforms u{decl.width, decl.height, 1 << iteration, static_cast<std::uint32_t>(s.kernel),
                   s.sigma_z,  s.sigma_n,   s.sigma_l};
  std::vector<Binding> bindings{{"color_in", r.color_in}, {"depth_normal", r.depth_normal}, {"color_out", r.color_out}};
  if (r.color_history) bindings.push_back({"color_history", *r.color_history});
  const hal::ShaderInfo& shader = r.color_history ? asvgf::shaders::atrous_history : asvgf::shaders::atrous_plain;
  const auto pipeline = pipelines.get<Uniforms>(shader);
  return add_compute_pass(graph, r.prefix + "atrous." + std::to_string(iteration + 1), shader, pipeline,
                          std::move(bindings), to_bytes(u), {u.width, u.height, 1});
}

}  // namespace asvgf::passes
