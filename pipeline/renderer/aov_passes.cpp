#include "renderer/aov_passes.hpp"

#include "asvgf/graph_runtime.hpp"
#include "shaders/export_aovs.hpp"
#include "shaders/widen_image.floats.hpp"
#include "shaders/widen_image.halves.hpp"

namespace asvgf::passes {

graph::PassBuilder add_export_aovs(graph::RenderGraph& graph, PipelineCache& pipelines, const ExportAovResources& r) {
  using Uniforms = asvgf::shaders::export_aovs_uniforms::Params;
  const auto& decl = graph.resource(r.depth);
  const Uniforms u{decl.width, decl.height};
  const hal::ShaderInfo& shader = asvgf::shaders::export_aovs;
  return add_compute_pass(graph, "export_aovs", shader, pipelines.get<Uniforms>(shader),
                          {{"depth_normal", r.depth_normal},
                           {"albedo", r.albedo},
                           {"depth_out", r.depth},
                           {"normal_out", r.normal},
                           {"albedo_out", r.albedo_out}},
                          to_bytes(u), {u.width, u.height, 1});
}

graph::PassBuilder add_image_widen(graph::RenderGraph& graph, PipelineCache& pipelines, const std::string& name,
                                   graph::ResourceId src, graph::ResourceId dst) {
  using Uniforms = asvgf::shaders::widen_image_floats_uniforms::Params;
  const auto& decl = graph.resource(src);
  const Uniforms u{decl.width, decl.height};
  // R32Uint: two halves a word (the G-buffer's motion)
  const hal::ShaderInfo& shader =
      decl.format == hal::Format::R32Uint ? asvgf::shaders::widen_image_halves : asvgf::shaders::widen_image_floats;
  return add_compute_pass(graph, name, shader, pipelines.get<Uniforms>(shader), {{"source", src}, {"target", dst}},
                          to_bytes(u), {u.width, u.height, 1});
}

graph::PassBuilder add_image_copy(graph::RenderGraph& graph, const std::string& name, graph::ResourceId src,
                                  graph::ResourceId dst) {
  return graph.add_pass(name)
      .read(src, graph::Use::CopySrc)
      .write(dst, graph::Use::CopyDst)
      .execute([src, dst](graph::PassContext& context) {
        context.commands().copy_image(context.image(src), context.image(dst));
      });
}

}  // namespace asvgf::passes
