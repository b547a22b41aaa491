#include "denoiser/passes/variance.hpp"

#include <cstddef>
#include <stdexcept>
#include <string>

#include "denoiser/passes/input_formats.hpp"
#include "denoiser/passes/temporal.hpp"
#include "shaders/variance.albedo_rgb9e5.hpp"
#include "shaders/variance.plain.hpp"

namespace asvgf::passes {
namespace {

// The shader's uniform block, as the shader tool generated it.
using Uniforms = asvgf::shaders::variance_plain_uniforms::Params;

}  // namespace

graph::PassBuilder add_variance(graph::RenderGraph& graph, PipelineCache& pipelines, const VarianceResources& r,
                                const DenoiseSettings& s) {
  if (graph.resource(r.integrated).format != hal::Format::R32Uint)
    throw std::invalid_argument("add_variance: the temporal result '" + graph.resource(r.integrated).name +
                                "' is R32Uint (RGB9E5 words, as a spatial chain keeps it)");
  require_moments_words(graph, r.moments, "add_variance");
  const auto& decl = graph.resource(r.color_variance);
  const Uniforms u{decl.width,   decl.height, s.sigma_z, s.sigma_n, luminance_sigma(s, decl.width, decl.height),
                   s.min_history};
  const hal::ShaderInfo& shader = albedo_rgb9e5(graph, r.albedo, "add_variance")
                                      ? asvgf::shaders::variance_albedo_rgb9e5
                                      : asvgf::shaders::variance_plain;
  const auto pipeline = pipelines.get<Uniforms>(shader);
  return add_compute_pass(graph, r.prefix + "variance", shader, pipeline,
                          {{"integrated", r.integrated},
                           {"moments", r.moments},
                           {"depth_normal", r.depth_normal},
                           {"color_variance", r.color_variance},
                           {"albedo", r.albedo}},
                          to_bytes(u), {u.width, u.height, 1});
}

}  // namespace asvgf::passes
