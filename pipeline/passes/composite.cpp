#include "passes/composite.hpp"

#include <cstddef>

#include "shaders/composite.hpp"

namespace asvgf::passes {
namespace {

// The shader's uniform block, as the shader tool generated it.
using Uniforms = asvgf::shaders::composite_uniforms::Params;

}  // namespace

graph::PassBuilder add_composite(graph::RenderGraph& graph, PipelineCache& pipelines, const CompositeResources& r,
                                 const DenoiseSettings& s) {
  const auto& decl = graph.resource(r.hdr);
  const Uniforms u{decl.width, decl.height, s.exposure, static_cast<std::uint32_t>(s.tonemap)};
  const hal::ShaderInfo& shader = asvgf::shaders::composite;
  const auto pipeline = pipelines.get<Uniforms>(shader);
  return add_compute_pass(graph, "composite", shader, pipeline,
                          {{"illumination", r.illumination},
                           {"albedo", r.albedo},
                           {"hdr", r.hdr},
                           {"display", r.display},
                           {"counters", r.counters}},
                          to_bytes(u), {u.width, u.height, 1});
}

}  // namespace asvgf::passes
