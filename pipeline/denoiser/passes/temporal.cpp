#include "denoiser/passes/temporal.hpp"

#include <array>
#include <cstddef>
#include <cstring>
#include <span>

#include "denoiser/graph/graph_runtime.hpp"
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
  const bool adaptive = s.adaptive && r.gradient.has_value();
  const auto& full = graph.resource(r.illumination);
  Uniforms u{full.width, full.height, 1, 1, s.alpha, s.moments_alpha, s.history_cap, 0};
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

SanitizeCounters::SanitizeCounters(hal::Device& device) : device_(device) {
  buffer_ = device_.create_buffer(
      {"sanitize_counters", kSize, hal::BufferUsage::Storage | hal::BufferUsage::CopySrc | hal::BufferUsage::CopyDst});
  const std::array<std::uint32_t, 4> zeros{};
  device_.upload_buffer(buffer_, 0, std::as_bytes(std::span(zeros)));
  state_ = hal::State::CopyDst;
}

SanitizeCounters::~SanitizeCounters() {
  device_.destroy(buffer_);
}

graph::ResourceId SanitizeCounters::import(graph::RenderGraph& graph) {
  const graph::ResourceId id = graph.import_buffer("sanitize_counters", buffer_, state_, kSize);
  // An output with a final state: the frame leaves the buffer in ShaderWrite whatever runs, so the
  // state recorded here for the next import is a guarantee, not an assumption about the passes.
  graph.output(id, hal::State::ShaderWrite);
  state_ = hal::State::ShaderWrite;
  return id;
}

SanitisedCounts SanitizeCounters::read() {
  device_.wait();
  if (state_ != hal::State::CopySrc) {
    auto cmd = device_.create_command_list("sanitize_counters readback");
    cmd->barrier({buffer_, state_, hal::State::CopySrc});
    device_.submit(*cmd);
    device_.wait();
    state_ = hal::State::CopySrc;
  }
  std::array<std::uint32_t, 4> values{};
  device_.read_buffer(buffer_, 0, std::as_writable_bytes(std::span(values)));
  return {values[0], values[1], values[2], values[3]};
}

}  // namespace asvgf::passes
