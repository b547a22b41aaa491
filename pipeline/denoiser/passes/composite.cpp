#include "denoiser/passes/composite.hpp"

#include <cstddef>
#include <stdexcept>

#include "denoiser/passes/input_formats.hpp"

#include "shaders/composite.local_mean.hpp"
#include "shaders/composite.local_mean_albedo_rgb9e5.hpp"
#include "shaders/composite.local_mean_half.hpp"
#include "shaders/composite.local_mean_half_albedo_rgb9e5.hpp"
#include "shaders/composite.local_mean_rgb9e5.hpp"
#include "shaders/composite.local_mean_rgb9e5_albedo_rgb9e5.hpp"
#include "shaders/composite.local_mean_rgb9e5_half.hpp"
#include "shaders/composite.local_mean_rgb9e5_half_albedo_rgb9e5.hpp"
#include "shaders/composite.one.hpp"
#include "shaders/composite.one_albedo_rgb9e5.hpp"
#include "shaders/composite.one_half.hpp"
#include "shaders/composite.one_half_albedo_rgb9e5.hpp"
#include "shaders/composite.split.hpp"
#include "shaders/composite.split_albedo_rgb9e5.hpp"
#include "shaders/composite.split_half.hpp"
#include "shaders/composite.split_half_albedo_rgb9e5.hpp"

namespace asvgf::passes {
namespace {

// The shader's uniform block, as the shader tool generated it.
using Uniforms = asvgf::shaders::composite_one_uniforms::Params;

}  // namespace

bool hdr_half(const graph::RenderGraph& graph, graph::ResourceId hdr, const std::string& caller) {
  const auto& decl = graph.resource(hdr);
  if (decl.kind == hal::ResourceKind::Image && decl.format == hal::Format::RGBA32F) return false;
  if (decl.kind == hal::ResourceKind::Image && decl.format == hal::Format::RGBA16F) return true;
  throw std::invalid_argument(caller + ": the radiance image '" + decl.name + "' is " +
                              std::string(hal::format_name(decl.format)) + ", not RGBA32F or RGBA16F");
}

graph::PassBuilder add_composite(graph::RenderGraph& graph, PipelineCache& pipelines, const CompositeResources& r,
                                 const DenoiseSettings& s) {
  const auto& decl = graph.resource(r.hdr);
  const bool split = r.specular.has_value();
  if (split && r.local_mean)
    throw std::invalid_argument("add_composite: the local-mean correction is applied here for one signal only");
  const auto& illumination = graph.resource(r.illumination);
  const bool rgb9e5 = illumination.kind == hal::ResourceKind::Image && illumination.format == hal::Format::R32Uint;
  if (rgb9e5 && !r.local_mean)
    throw std::invalid_argument("add_composite: an RGB9E5 illumination ('" + illumination.name +
                                "', R32Uint) is read with the local-mean correction only");
  const LocalMeanBlocks blocks = r.local_mean ? r.local_mean->blocks : LocalMeanBlocks{};
  const Uniforms u{decl.width,    decl.height, s.exposure, static_cast<std::uint32_t>(s.tonemap),
                   blocks.radius, blocks.block};
  namespace sh = asvgf::shaders;
  const bool half = hdr_half(graph, r.hdr, "add_composite");
  const bool albedo_words = albedo_rgb9e5(graph, r.albedo, "add_composite");
  const auto albedo = [albedo_words](const hal::ShaderInfo& floats, const hal::ShaderInfo& words) -> const auto& {
    return albedo_words ? words : floats;
  };
  const hal::ShaderInfo& shader =
      split ? (half ? albedo(sh::composite_split_half, sh::composite_split_half_albedo_rgb9e5)
                    : albedo(sh::composite_split, sh::composite_split_albedo_rgb9e5))
      : r.local_mean
          ? (rgb9e5 ? (half ? albedo(sh::composite_local_mean_rgb9e5_half,
                                     sh::composite_local_mean_rgb9e5_half_albedo_rgb9e5)
                            : albedo(sh::composite_local_mean_rgb9e5, sh::composite_local_mean_rgb9e5_albedo_rgb9e5))
                    : (half ? albedo(sh::composite_local_mean_half, sh::composite_local_mean_half_albedo_rgb9e5)
                            : albedo(sh::composite_local_mean, sh::composite_local_mean_albedo_rgb9e5)))
          : (half ? albedo(sh::composite_one_half, sh::composite_one_half_albedo_rgb9e5)
                  : albedo(sh::composite_one, sh::composite_one_albedo_rgb9e5));
  const auto pipeline = pipelines.get<Uniforms>(shader);
  std::vector<Binding> bindings{{"illumination", r.illumination},
                                {"albedo", r.albedo},
                                {"hdr", r.hdr},
                                {"display", r.display},
                                {"counters", r.counters}};
  if (split)
    bindings.insert(bindings.end(), {{"specular", *r.specular}, {"specular_albedo", r.specular_albedo.value()}});
  if (r.local_mean) bindings.push_back({"box_means", r.local_mean->box_means});
  return add_compute_pass(graph, "composite", shader, pipeline, std::move(bindings), to_bytes(u),
                          {u.width, u.height, 1});
}

}  // namespace asvgf::passes
