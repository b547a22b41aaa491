#include "denoiser/passes/atrous.hpp"

#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "denoiser/passes/input_formats.hpp"
#include "denoiser/passes/temporal.hpp"
#include "shaders/atrous.first.hpp"
#include "shaders/atrous.first_albedo_rgb9e5.hpp"
#include "shaders/atrous.first_history.hpp"
#include "shaders/atrous.first_history_albedo_rgb9e5.hpp"
#include "shaders/atrous.first_history_sums.hpp"
#include "shaders/atrous.first_history_sums_albedo_rgb9e5.hpp"
#include "shaders/atrous.first_sums.hpp"
#include "shaders/atrous.first_sums_albedo_rgb9e5.hpp"
#include "shaders/atrous.history.hpp"
#include "shaders/atrous.last.hpp"
#include "shaders/atrous.last_composite.hpp"
#include "shaders/atrous.last_composite_albedo_rgb9e5.hpp"
#include "shaders/atrous.last_composite_half.hpp"
#include "shaders/atrous.last_composite_half_albedo_rgb9e5.hpp"
#include "shaders/atrous.last_history.hpp"
#include "shaders/atrous.last_history_composite.hpp"
#include "shaders/atrous.last_history_composite_albedo_rgb9e5.hpp"
#include "shaders/atrous.last_history_composite_half.hpp"
#include "shaders/atrous.last_history_composite_half_albedo_rgb9e5.hpp"
#include "shaders/atrous.last_sums.hpp"
#include "shaders/atrous.last_sums_rgb9e5.hpp"
#include "shaders/atrous.middle.hpp"
#include "shaders/atrous.middle_corrects_history.hpp"
#include "shaders/atrous.middle_history.hpp"
#include "shaders/atrous.plain.hpp"

namespace asvgf::passes {
namespace {

// The uniform block as the shader tool generated it (every variant has the same block).
using Uniforms = asvgf::shaders::atrous_plain_uniforms::Params;

// The variant for the chain position: a storage buffer (the packed filter texels) in or out, the
// history tap, composite folded in, the local mean's block sums or history correction; those that
// read the albedo (the first packed iteration, the composite) as RGB9E5 words or floats.
const hal::ShaderInfo& atrous_shader(bool packed_in, bool packed_out, bool history, bool composite, bool sums,
                                     bool corrects_history, bool rgb9e5_out, bool hdr_half, bool albedo_words) {
  namespace sh = asvgf::shaders;
  const auto albedo = [albedo_words](const hal::ShaderInfo& floats, const hal::ShaderInfo& words) -> const auto& {
    return albedo_words ? words : floats;
  };
  if (corrects_history) return sh::atrous_middle_corrects_history;
  if (rgb9e5_out) return sh::atrous_last_sums_rgb9e5;
  if (sums && packed_in) return sh::atrous_last_sums;
  if (sums)
    return history ? albedo(sh::atrous_first_history_sums, sh::atrous_first_history_sums_albedo_rgb9e5)
                   : albedo(sh::atrous_first_sums, sh::atrous_first_sums_albedo_rgb9e5);
  if (composite && hdr_half)
    return history
               ? albedo(sh::atrous_last_history_composite_half, sh::atrous_last_history_composite_half_albedo_rgb9e5)
               : albedo(sh::atrous_last_composite_half, sh::atrous_last_composite_half_albedo_rgb9e5);
  if (composite)
    return history ? albedo(sh::atrous_last_history_composite, sh::atrous_last_history_composite_albedo_rgb9e5)
                   : albedo(sh::atrous_last_composite, sh::atrous_last_composite_albedo_rgb9e5);
  if (packed_in) {
    if (packed_out) return history ? sh::atrous_middle_history : sh::atrous_middle;
    return history ? sh::atrous_last_history : sh::atrous_last;
  }
  if (packed_out)
    return history ? albedo(sh::atrous_first_history, sh::atrous_first_history_albedo_rgb9e5)
                   : albedo(sh::atrous_first, sh::atrous_first_albedo_rgb9e5);
  return history ? sh::atrous_history : sh::atrous_plain;
}

}  // namespace

graph::PassBuilder add_atrous(graph::RenderGraph& graph, PipelineCache& pipelines, const AtrousResources& r,
                              int iteration, const DenoiseSettings& s) {
  const auto& decl = graph.resource(r.depth_normal);
  const bool packed_in = graph.resource(r.color_in).kind == hal::ResourceKind::Buffer;
  const bool composite = r.composite.has_value();
  const bool packed_out = !composite && graph.resource(r.color_out).kind == hal::ResourceKind::Buffer;
  if (composite && (!packed_in || r.composite->specular))
    throw std::invalid_argument("add_atrous: only a one-signal chain's last packed-in iteration composites");
  if (packed_out && !packed_in && iteration != 0)
    throw std::invalid_argument("add_atrous: packed filter texels from an RGBA16F input only at iteration 0 (step 1)");
  if ((packed_in || packed_out) && !r.surface)
    throw std::invalid_argument("add_atrous: a packed iteration needs the surface texels' buffer");
  const bool first_packed = packed_out && !packed_in;
  if (first_packed != r.estimate.has_value())
    throw std::invalid_argument(
        first_packed ? "add_atrous: the first packed iteration estimates the variance: it needs moments and albedo"
                     : "add_atrous: only the first packed iteration reads the variance estimate's moments and albedo");
  if (r.local_mean_sums) {
    const bool first = first_packed && !r.local_mean_sums->temporal_sums;
    const bool last = packed_in && !packed_out && !composite && !r.color_history && r.local_mean_sums->temporal_sums;
    if (!first && !last)
      throw std::invalid_argument(
          "add_atrous: the local mean's block sums come from the first packed iteration, or from a packed-in last "
          "iteration without the history tap with the temporal terms' sums");
    const int b = r.local_mean_sums->block;
    if (b != 1 && b != 2 && b != 4 && b != 8)
      throw std::invalid_argument("add_atrous: the local mean's blocks are 1, 2, 4 or 8 pixels, not " +
                                  std::to_string(b));
  }
  const auto& out_decl = graph.resource(r.color_out);
  const bool rgb9e5_out =
      !composite && out_decl.kind == hal::ResourceKind::Image && out_decl.format == hal::Format::R32Uint;
  if (rgb9e5_out && !(packed_in && !r.color_history && r.local_mean_sums))
    throw std::invalid_argument("add_atrous: an RGB9E5 (R32Uint) color_out '" + out_decl.name +
                                "' is written by a packed-in last iteration with the local mean's block sums only");
  const auto rgb9e5_words = [&graph](graph::ResourceId id, const char* what) {
    if (graph.resource(id).format != hal::Format::R32Uint)
      throw std::invalid_argument(std::string("add_atrous: ") + what + " '" + graph.resource(id).name +
                                  "' is R32Uint (RGB9E5 words, as a spatial chain keeps it)");
  };
  if (r.color_history) rgb9e5_words(*r.color_history, "the colour history");
  if (r.estimate) require_moments_words(graph, r.estimate->moments, "add_atrous");
  if (first_packed) rgb9e5_words(r.color_in, "the first packed iteration's temporal result");
  if (r.corrects_history && !(packed_in && packed_out && r.color_history))
    throw std::invalid_argument(
        "add_atrous: only a packed middle iteration corrects the colour history, and it "
        "needs color_history");
  // Every image and buffer must cover depth_normal's size, over which the pass dispatches.
  std::vector<graph::ResourceId> covering{r.color_in};
  if (composite)
    covering.insert(covering.end(), {r.composite->albedo, r.composite->hdr, r.composite->display});
  else
    covering.push_back(r.color_out);
  if (r.surface) covering.push_back(*r.surface);
  if (r.estimate) covering.insert(covering.end(), {r.estimate->moments, r.estimate->albedo});
  for (const graph::ResourceId id : covering) {
    const auto& other = graph.resource(id);
    const bool covers = other.kind == hal::ResourceKind::Buffer
                            ? other.size >= std::uint64_t{8} * decl.width * decl.height
                            : other.width == decl.width && other.height == decl.height;
    if (!covers)
      throw std::invalid_argument("add_atrous: '" + other.name + "' does not match depth_normal's " +
                                  std::to_string(decl.width) + "x" + std::to_string(decl.height));
  }
  const Uniforms u{decl.width,
                   decl.height,
                   1 << iteration,
                   static_cast<std::uint32_t>(s.kernel),
                   s.sigma_z,
                   s.sigma_n,
                   luminance_sigma(s, decl.width, decl.height),
                   s.min_history,
                   s.exposure,
                   static_cast<std::uint32_t>(s.tonemap),
                   r.local_mean_sums    ? r.local_mean_sums->block
                   : r.corrects_history ? r.corrects_history->block
                                        : 1,
                   r.corrects_history ? r.corrects_history->radius : 0};
  std::vector<Binding> bindings{{first_packed ? "integrated" : "color_in", r.color_in}};
  if (composite)
    bindings.insert(bindings.end(), {{"albedo", r.composite->albedo},
                                     {"hdr", r.composite->hdr},
                                     {"display", r.composite->display},
                                     {"counters", r.composite->counters}});
  else
    bindings.push_back({"color_out", r.color_out});
  if (first_packed) bindings.insert(bindings.end(), {{"moments", r.estimate->moments}, {"albedo", r.estimate->albedo}});
  if (packed_in || first_packed) bindings.push_back({"surface", *r.surface});
  if (!packed_in) bindings.push_back({"depth_normal", r.depth_normal});
  if (r.color_history) bindings.push_back({"color_history", *r.color_history});
  if (r.local_mean_sums) {
    bindings.push_back({"block_sums", r.local_mean_sums->block_sums});
    if (r.local_mean_sums->temporal_sums) bindings.push_back({"temporal_sums", *r.local_mean_sums->temporal_sums});
  }
  if (r.corrects_history) bindings.push_back({"box_means", r.corrects_history->box_means});
  const bool albedo_words = composite    ? albedo_rgb9e5(graph, r.composite->albedo, "add_atrous")
                            : r.estimate ? albedo_rgb9e5(graph, r.estimate->albedo, "add_atrous")
                                         : false;
  const hal::ShaderInfo& shader =
      atrous_shader(packed_in, packed_out, r.color_history.has_value(), composite, r.local_mean_sums.has_value(),
                    r.corrects_history.has_value(), rgb9e5_out,
                    composite && hdr_half(graph, r.composite->hdr, "add_atrous"), albedo_words);
  const auto pipeline = pipelines.get<Uniforms>(shader);
  const std::string name =
      r.prefix + "atrous." + std::to_string(iteration + 1) + (composite ? "+composite" : "") + r.name_suffix;
  return add_compute_pass(graph, name, shader, pipeline, std::move(bindings), to_bytes(u), {u.width, u.height, 1});
}

}  // namespace asvgf::passes
