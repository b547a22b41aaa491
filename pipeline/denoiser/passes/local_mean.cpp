#include "denoiser/passes/local_mean.hpp"

#include "shaders/local_mean.columns.hpp"
#include "shaders/local_mean.rows.hpp"

namespace asvgf::passes {
namespace {

// The shaders' uniform block, as the shader tool generated it (the same for both variants).
using Uniforms = asvgf::shaders::local_mean_rows_uniforms::Params;

}  // namespace

void add_local_mean(graph::RenderGraph& graph, PipelineCache& pipelines, const LocalMeanResources& r,
                    const DenoiseSettings& s) {
  const auto& decl = graph.resource(r.corrected);
  const Uniforms u{decl.width, decl.height, (s.local_mean - 1) / 2, r.gated ? 1u : 0u};
  const graph::ResourceId rows = graph.add_image(r.name + "_rows", decl.width, decl.height, hal::Format::RGBA32F);
  const hal::ShaderInfo& rows_shader = asvgf::shaders::local_mean_rows;
  add_compute_pass(graph, r.name + ".rows", rows_shader, pipelines.get<Uniforms>(rows_shader),
                   {{"temporal", r.temporal}, {"filtered", r.filtered}, {"row_means", rows}}, to_bytes(u),
                   {u.width, u.height, 1});
  const hal::ShaderInfo& columns_shader = asvgf::shaders::local_mean_columns;
  // An invocation a strip of rows of one column (local_mean.comp, kStrip).
  constexpr std::uint32_t kStrip = 16;
  add_compute_pass(graph, r.name, columns_shader, pipelines.get<Uniforms>(columns_shader),
                   {{"row_means", rows}, {"filtered", r.filtered}, {"corrected", r.corrected}}, to_bytes(u),
                   {u.width, (u.height + kStrip - 1) / kStrip, 1});
}

}  // namespace asvgf::passes
