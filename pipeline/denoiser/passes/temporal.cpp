#include "denoiser/passes/temporal.hpp"

#include <cstddef>
#include <cstring>

#include "asvgf/graph_runtime.hpp"
#include "shaders/temporal.adaptive.hpp"
#include "shaders/temporal.adaptive_virtual.hpp"
#include "shaders/temporal.constant.hpp"
#include "shaders/temporal.constant_virtual.hpp"

namespace asvgf::passes {
namespace {

// The uniform block as the shader tool generated it (every variant has the same block).
using Uniforms = asvgf::shaders::temporal_constant_uniforms::Params;

}  // namespace

graph::PassBuilder add_temporal(graph::RenderGraph& graph, PipelineCache& pipelines, const TemporalResources& r,
                                const DenoiseSettings& s) {
  const bool adaptive = r.gradient.has_value();
  const auto& full = graph.resource(r.illumination);
  Uniforms u{full.width, full.height, 1, 1, s.alpha, s.moments_alpha, s.history_cap, 0, s.antilag};
  if (adaptive) {
    const auto& g = graph.resource(*r.gradient);
    u.gradient_width = g.width;
    u.gradient_height = g.height;
  }
  const hal::ShaderInfo* shader =
      r.virtual_motion
          ? (adaptive ? &asvgf::shaders::temporal_adaptive_virtual : &asvgf::shaders::temporal_constant_virtual)
          : (adaptive ? &asvgf::shaders::temporal_adaptive : &asvgf::shaders::temporal_constant);
  const hal::PipelineHandle pipeline = pipelines.get<Uniforms>(*shader);
  std::vector<Binding> bindings{{"illumination", r.illumination},
                                {"motion", r.motion},
                                {"depth_normal", r.depth_normal},
                                {"prev_depth_normal", r.depth_normal, true},
                                {"prev_color", r.color_history, true},
                                {"prev_moments", r.moments, true},
                                {"integrated", r.integrated},
                                {"moments", r.moments},
                                {"counters", r.counters}};
  if (adaptive) bindings.push_back({"gradient", *r.gradient});
  // Whether the histories hold anything is known only when the pass executes. The counters need no
  // barrier of their own: SanitizeCounters::import makes them an output whose final barrier orders
  // each frame's atomics before the next frame's.
  return add_compute_pass(graph, r.prefix + "temporal", *shader, pipeline, std::move(bindings), to_bytes(u),
                          {u.width, u.height, 1}, [r](graph::PassContext& ctx, std::vector<std::byte>& uniforms) {
                            const std::uint32_t valid = ctx.history_valid(r.depth_normal) &&
                                                        ctx.history_valid(r.color_history) &&
                                                        ctx.history_valid(r.moments);
                            std::memcpy(uniforms.data() + offsetof(Uniforms, history_valid), &valid, sizeof valid);
                          });
}

}  // namespace asvgf::passes
