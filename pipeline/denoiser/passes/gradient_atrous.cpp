#include "denoiser/passes/gradient_atrous.hpp"

#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "shaders/gradient_atrous.first.hpp"
#include "shaders/gradient_atrous.plain.hpp"
#include "shaders/gradient_atrous.rest.hpp"
#include "shaders/gradient_atrous.samples.hpp"
#include "shaders/gradient_atrous.samples_first.hpp"

namespace asvgf::passes {
namespace {

// The shader's uniform block, as the shader tool generated it.
using Uniforms = asvgf::shaders::gradient_atrous_plain_uniforms::Params;

}  // namespace

graph::PassBuilder add_gradient_atrous(graph::RenderGraph& graph, PipelineCache& pipelines,
                                       const GradientAtrousResources& r, int iteration, const DenoiseSettings& s) {
  namespace sh = asvgf::shaders;
  const auto& full = graph.resource(r.depth_normal);
  const auto& out = graph.resource(r.gradient_out);
  if (r.strata_guide_in && r.strata_guide_out)
    throw std::invalid_argument("add_gradient_atrous: an iteration reads or writes the strata guide, not both");
  for (const auto& guide : {r.strata_guide_in, r.strata_guide_out}) {
    if (!guide) continue;
    const auto& decl = graph.resource(*guide);
    if (decl.width != out.width || decl.height != out.height)
      throw std::invalid_argument("add_gradient_atrous: '" + decl.name + "' is not the gradient's " +
                                  std::to_string(out.width) + "x" + std::to_string(out.height));
  }
  if (r.samples_in && (r.strata_guide_in || iteration != 0))
    throw std::invalid_argument("add_gradient_atrous: only the first iteration (step 1) reads the gradient samples");
  const Uniforms u{full.width,     full.height, out.width, out.height,
                   1 << iteration, s.sigma_z,   s.sigma_n, r.luminance_in_alpha ? 1u : 0u};
  std::vector<Binding> bindings{{"gradient_in", r.gradient_in}, {"gradient_out", r.gradient_out}};
  const hal::ShaderInfo* shader = r.samples_in ? &sh::gradient_atrous_samples : &sh::gradient_atrous_plain;
  if (r.strata_guide_in) {
    shader = &sh::gradient_atrous_rest;
    bindings.push_back({"strata_guide", *r.strata_guide_in});
  } else {
    bindings.push_back({"depth_normal", r.depth_normal});
  }
  if (r.strata_guide_out) {
    shader = r.samples_in ? &sh::gradient_atrous_samples_first : &sh::gradient_atrous_first;
    bindings.push_back({"strata_guide_out", *r.strata_guide_out});
  }
  const auto pipeline = pipelines.get<Uniforms>(*shader);
  return add_compute_pass(graph, "gradient_atrous." + std::to_string(iteration + 1), *shader, pipeline,
                          std::move(bindings), to_bytes(u), {u.gradient_width, u.gradient_height, 1});
}

}  // namespace asvgf::passes
