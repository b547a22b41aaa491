#include "passes/composite.hpp"

#include <cstddef>

#include "shaders/composite.hpp"

namespace asvgf::passes {
namespace {

struct Uniforms {
  std::uint32_t width, height;
  float exposure;
  std::uint32_t tonemap;
};
static_assert(sizeof(Uniforms) == 16);

}  // namespace

graph::PassBuilder add_composite(graph::RenderGraph& graph, PipelineCache& pipelines, const CompositeResources& r,
                                 const DenoiseSettings& s) {
  const auto& decl = graph.resource(r.hdr);
  const Uniforms u{decl.width, decl.height, s.exposure, static_cast<std::uint32_t>(s.tonemap)};
  const hal::ShaderInfo& shader = asvgf::shaders::composite;
  const auto pipeline = pipelines.get(shader, sizeof(Uniforms),
                                      {{"width", offsetof(Uniforms, width)},
                                       {"height", offsetof(Uniforms, height)},
                                       {"exposure", offsetof(Uniforms, exposure)},
                                       {"tonemap", offsetof(Uniforms, tonemap)}});
  return add_compute_pass(graph, "composite", shader, pipeline,
                          {{"illumination", r.illumination},
                           {"albedo", r.albedo},
                           {"hdr", r.hdr},
                           {"display", r.display},
                           {"counters", r.counters}},
                          to_bytes(u), {u.width, u.height, 1});
}

}  // namespace asvgf::passes
