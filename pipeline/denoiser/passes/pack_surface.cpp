#include "denoiser/passes/pack_surface.hpp"

#include "shaders/pack_surface.hpp"

namespace asvgf::passes {

graph::PassBuilder add_pack_surface(graph::RenderGraph& graph, PipelineCache& pipelines, const PackSurfaceResources& r,
                                    bool depth_gradient_given) {
  using Uniforms = asvgf::shaders::pack_surface_uniforms::Params;
  const auto& decl = graph.resource(r.depth_normal);
  const Uniforms u{decl.width, decl.height, depth_gradient_given ? 1u : 0u, 0u};
  const hal::ShaderInfo& shader = asvgf::shaders::pack_surface;
  return add_compute_pass(graph, "pack_surface", shader, pipelines.get<Uniforms>(shader),
                          {{"depth", r.depth}, {"normal", r.normal}, {"depth_normal", r.depth_normal}}, to_bytes(u),
                          {u.width, u.height, 1});
}

}  // namespace asvgf::passes
