#include "passes/atrous.hpp"

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "shaders/atrous.first.hpp"
#include "shaders/atrous.first_history.hpp"
#include "shaders/atrous.first_tile.hpp"
#include "shaders/atrous.first_tile_history.hpp"
#include "shaders/atrous.history.hpp"
#include "shaders/atrous.last.hpp"
#include "shaders/atrous.last_history.hpp"
#include "shaders/atrous.middle.hpp"
#include "shaders/atrous.middle_history.hpp"
#include "shaders/atrous.plain.hpp"

namespace asvgf::passes {
namespace {

// The uniform block as the shader tool generated it (every variant has the same block).
using Uniforms = asvgf::shaders::atrous_plain_uniforms::Params;

// The variant for the formats the graph declared (RGBA32Uint is the packed filter texel) and the
// step: the first iteration of a chain (step 1) reads its taps from a shared-memory tile.
const hal::ShaderInfo& atrous_shader(bool packed_in, bool packed_out, bool history, int step) {
  namespace sh = asvgf::shaders;
  if (packed_in) {
    if (packed_out) return history ? sh::atrous_middle_history : sh::atrous_middle;
    return history ? sh::atrous_last_history : sh::atrous_last;
  }
  if (packed_out && step == 1) return history ? sh::atrous_first_tile_history : sh::atrous_first_tile;
  if (packed_out) return history ? sh::atrous_first_history : sh::atrous_first;
  return history ? sh::atrous_history : sh::atrous_plain;
}

}  // namespace

graph::PassBuilder add_atrous(graph::RenderGraph& graph, PipelineCache& pipelines, const AtrousResources& r,
                              int iteration, const DenoiseSettings& s) {
  const auto& decl = graph.resource(r.color_out);
  const Uniforms u{decl.width, decl.height, 1 << iteration, static_cast<std::uint32_t>(s.kernel),
                   s.sigma_z,  s.sigma_n,   s.sigma_l};
  std::vector<Binding> bindings{{"color_in", r.color_in}, {"depth_normal", r.depth_normal}, {"color_out", r.color_out}};
  if (r.color_history) bindings.push_back({"color_history", *r.color_history});
  const hal::ShaderInfo& shader =
      atrous_shader(graph.resource(r.color_in).format == hal::Format::RGBA32Uint,
                    decl.format == hal::Format::RGBA32Uint, r.color_history.has_value(), u.step);
  const auto pipeline = pipelines.get<Uniforms>(shader);
  return add_compute_pass(graph, r.prefix + "atrous." + std::to_string(iteration + 1), shader, pipeline,
                          std::move(bindings), to_bytes(u), {u.width, u.height, 1});
}

}  // namespace asvgf::passes
