#include "denoiser/passes/temporal.hpp"

#include <cstddef>
#include <cstring>
#include <stdexcept>

#include "asvgf/graph_runtime.hpp"
#include "denoiser/passes/input_formats.hpp"
#include "shaders/temporal.adaptive.hpp"
#include "shaders/temporal.adaptive_halves.hpp"
#include "shaders/temporal.adaptive_rgb9e5.hpp"
#include "shaders/temporal.adaptive_rgb9e5_halves.hpp"
#include "shaders/temporal.adaptive_virtual.hpp"
#include "shaders/temporal.adaptive_virtual_rgb9e5.hpp"
#include "shaders/temporal.constant.hpp"
#include "shaders/temporal.constant_halves.hpp"
#include "shaders/temporal.constant_rgb9e5.hpp"
#include "shaders/temporal.constant_rgb9e5_halves.hpp"
#include "shaders/temporal.constant_virtual.hpp"
#include "shaders/temporal.constant_virtual_rgb9e5.hpp"

namespace asvgf::passes {
namespace {

// The uniform block as the shader tool generated it (every variant has the same block).
using Uniforms = asvgf::shaders::temporal_constant_uniforms::Params;

const hal::ShaderInfo& temporal_shader(bool adaptive, bool virtual_motion, bool rgb9e5, bool halves) {
  namespace sh = asvgf::shaders;
  if (rgb9e5 && halves) return adaptive ? sh::temporal_adaptive_rgb9e5_halves : sh::temporal_constant_rgb9e5_halves;
  if (halves) return adaptive ? sh::temporal_adaptive_halves : sh::temporal_constant_halves;
  if (rgb9e5)
    return virtual_motion ? (adaptive ? sh::temporal_adaptive_virtual_rgb9e5 : sh::temporal_constant_virtual_rgb9e5)
                          : (adaptive ? sh::temporal_adaptive_rgb9e5 : sh::temporal_constant_rgb9e5);
  return virtual_motion ? (adaptive ? sh::temporal_adaptive_virtual : sh::temporal_constant_virtual)
                        : (adaptive ? sh::temporal_adaptive : sh::temporal_constant);
}

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
  const hal::Format history_format = graph.resource(r.color_history).format;
  const bool rgb9e5 = history_format == hal::Format::R32Uint;
  if (graph.resource(r.integrated).format != history_format || (!rgb9e5 && history_format != hal::Format::RGBA16F))
    throw std::invalid_argument("add_temporal: '" + graph.resource(r.color_history).name + "' and '" +
                                graph.resource(r.integrated).name +
                                "' are both RGBA16F or both R32Uint (RGB9E5 words)");
  require_moments_words(graph, r.moments, "add_temporal");
  const bool halves = motion_halves(graph, r.motion, "add_temporal");
  if (halves && r.virtual_motion)
    throw std::invalid_argument("add_temporal: the virtual motion '" + graph.resource(r.motion).name +
                                "' is a float format (its z flags the reflected history), not R32Uint");
  const hal::ShaderInfo* shader = &temporal_shader(adaptive, r.virtual_motion, rgb9e5, halves);
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

void require_moments_words(const graph::RenderGraph& graph, graph::ResourceId moments, const std::string& pass) {
  if (graph.resource(moments).format != hal::Format::R32Uint)
    throw std::invalid_argument(pass + ": the moments '" + graph.resource(moments).name +
                                "' are R32Uint (E[l], sqrt(Var[l]) and n in one word)");
}

}  // namespace asvgf::passes
