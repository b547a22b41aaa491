#include "denoiser/passes/gradient.hpp"

#include <cstddef>
#include <cstring>

#include "denoiser/passes/input_formats.hpp"
#include "shaders/gradient.given.hpp"
#include "shaders/gradient.in_illumination.hpp"
#include "shaders/gradient_reprojected.floats.hpp"
#include "shaders/gradient_reprojected.halves.hpp"

namespace asvgf::passes {
namespace {

// The shader's uniform block, as the shader tool generated it.
using Uniforms = asvgf::shaders::gradient_in_illumination_uniforms::Params;

}  // namespace

graph::PassBuilder add_gradient(graph::RenderGraph& graph, PipelineCache& pipelines, const GradientResources& r) {
  const auto& full = graph.resource(r.illumination);
  const auto& out = graph.resource(r.gradient);
  const Uniforms u{full.width, full.height, out.width, out.height, r.luminance_in_alpha ? 1u : 0u, 0, 0, 0};
  const hal::ShaderInfo& shader =
      r.current_given ? asvgf::shaders::gradient_given : asvgf::shaders::gradient_in_illumination;
  std::vector<Binding> bindings = {{"gradient_prev", r.gradient_prev}, {"gradient", r.gradient}};
  if (!r.current_given) bindings.push_back({"illumination", r.illumination});
  return add_compute_pass(graph, "gradient", shader, pipelines.get<Uniforms>(shader), std::move(bindings), to_bytes(u),
                          {u.gradient_width, u.gradient_height, 1});
}

// One 12x9 workgroup per 4x3 strata (the shader's layout).
graph::PassBuilder add_gradient_reprojected(graph::RenderGraph& graph, PipelineCache& pipelines,
                                            const ReprojectedGradientResources& r) {
  using Params = asvgf::shaders::gradient_reprojected_floats_uniforms::Params;
  const auto& full = graph.resource(r.illumination);
  const auto& out = graph.resource(r.gradient);
  const Params u{full.width, full.height, out.width, out.height, 0u};
  const hal::ShaderInfo& shader = motion_halves(graph, r.motion, "add_gradient_reprojected")
                                      ? asvgf::shaders::gradient_reprojected_halves
                                      : asvgf::shaders::gradient_reprojected_floats;
  return add_compute_pass(graph, "gradient_reprojected", shader, pipelines.get<Params>(shader),
                          {{"illumination", r.illumination},
                           {"motion", r.motion},
                           {"depth_normal", r.depth_normal},
                           {"prev_depth_normal", r.depth_normal, true},
                           {"prev_noisy_luminance", r.luminance, true},
                           {"noisy_luminance", r.luminance},
                           {"gradient", r.gradient}},
                          to_bytes(u), {groups_for(u.gradient_width, 4) * 12, groups_for(u.gradient_height, 3) * 9, 1},
                          [r](graph::PassContext& ctx, std::vector<std::byte>& uniforms) {
                            const std::uint32_t valid =
                                ctx.history_valid(r.depth_normal) && ctx.history_valid(r.luminance);
                            std::memcpy(uniforms.data() + offsetof(Params, history_valid), &valid, sizeof valid);
                          });
}

}  // namespace asvgf::passes
