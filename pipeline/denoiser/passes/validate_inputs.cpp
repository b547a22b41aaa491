#include "denoiser/passes/validate_inputs.hpp"

#include <cstring>

#include "shaders/validate_inputs.hpp"

namespace asvgf::passes {

void add_validate_inputs(graph::RenderGraph& graph, PipelineCache& pipelines, const ValidateInputsResources& r) {
  using Params = asvgf::shaders::validate_inputs_uniforms::Params;
  graph.add_pass("validate_clear").write(r.counts, graph::Use::CopyDst).execute([r](graph::PassContext& ctx) {
    ctx.commands().clear_buffer(hal::BufferHandle{ctx.resource(r.counts).id}, 0);
  });
  const auto& decl = graph.resource(r.illumination);
  const Params u{decl.width, decl.height, 0u, 0u};
  const hal::ShaderInfo& shader = asvgf::shaders::validate_inputs;
  add_compute_pass(graph, "validate_inputs", shader, pipelines.get<Params>(shader),
                   {{"illumination", r.illumination},
                    {"albedo", r.albedo},
                    {"normal", r.normal},
                    {"depth", r.depth},
                    {"motion", r.motion},
                    {"prev_depth_normal", r.depth_normal, true},
                    {"counts", r.counts}},
                   to_bytes(u), {u.width, u.height, 1}, [r](graph::PassContext& ctx, std::vector<std::byte>& uniforms) {
                     const std::uint32_t valid = ctx.history_valid(r.depth_normal);
                     std::memcpy(uniforms.data() + offsetof(Params, history_valid), &valid, sizeof valid);
                   });
}

}  // namespace asvgf::passes
