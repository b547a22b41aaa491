#include "passes/denoiser.hpp"

#include <string>

#include "passes/atrous.hpp"
#include "passes/composite.hpp"
#include "passes/gradient.hpp"
#include "passes/gradient_atrous.hpp"
#include "passes/temporal.hpp"
#include "passes/variance.hpp"

namespace asvgf::passes {

DenoiserOutputs add_denoiser(graph::RenderGraph& graph, PipelineCache& pipelines, const DenoiserInputs& in,
                             const DenoiseSettings& s, Filter filter) {
  using F = hal::Format;
  using graph::Lifetime;
  using graph::ResourceId;
  const auto& decl = graph.resource(in.illumination);
  const std::uint32_t w = decl.width, h = decl.height;
  DenoiserOutputs out;
  out.filtered = in.illumination;

  const bool filtered = s.adaptive && filter != Filter::None;
  const bool reprojected = filtered && s.gradient_source == GradientSource::Reprojected;
  if (reprojected || (filtered && in.gradient_prev)) {
    // Re-shaded: declared on still frames too, so that dump() shows them left out with the reason.
    // Reprojected: runs on every frame, still ones too: its luminance is the next frame's history.
    const bool skip = !reprojected && !in.gradient_skip_reason.empty();
    const std::uint32_t gw = (w + 2) / 3, gh = (h + 2) / 3;  // one stratum per 3x3 pixels
    ResourceId current = graph.add_image("gradient", gw, gh, F::RGBA16F);
    if (reprojected) {
      const ResourceId luminance = graph.add_image("noisy_luminance", w, h, F::R32F, Lifetime::Persistent);
      add_gradient_reprojected(graph, pipelines, {in.illumination, in.motion, in.depth_normal, luminance, current});
    } else {
      add_gradient(graph, pipelines, {in.illumination, *in.gradient_prev, current})
          .skip_if(skip, in.gradient_skip_reason);
    }
    for (int i = 0; i < s.gradient_iterations; ++i) {
      const ResourceId next = graph.add_image("gradient." + std::to_string(i + 1), gw, gh, F::RGBA16F);
      add_gradient_atrous(graph, pipelines, {current, in.depth_normal, next}, i, s)
          .skip_if(skip, in.gradient_skip_reason);
      current = next;
    }
    if (!skip) out.gradient = current;
  }

  if (filter != Filter::None) {
    const ResourceId color_history = graph.add_image("color_history", w, h, F::RGBA16F, Lifetime::Persistent);
    const ResourceId moments = graph.add_image("moments", w, h, F::RGBA32F, Lifetime::Persistent);
    const bool spatial = filter == Filter::Spatiotemporal && s.atrous_iterations > 0;
    // Without a spatial filter the temporal result is itself next frame's colour history.
    const ResourceId integrated = spatial ? graph.add_image("integrated", w, h, F::RGBA16F) : color_history;
    add_temporal(
        graph, pipelines,
        {in.illumination, in.motion, in.depth_normal, color_history, moments, integrated, in.counters, out.gradient},
        s);
    out.filtered = integrated;
    out.moments = moments;
    out.integrated = integrated;
    out.variance = integrated;
    out.color_history = color_history;
    if (spatial) {
      ResourceId current = graph.add_image("color_variance", w, h, F::RGBA16F);
      out.variance = current;
      add_variance(graph, pipelines, {integrated, moments, in.depth_normal, current}, s);
      for (int i = 0; i < s.atrous_iterations; ++i) {
        const ResourceId next = graph.add_image("atrous." + std::to_string(i + 1), w, h, F::RGBA16F);
        add_atrous(graph, pipelines,
                   {current, in.depth_normal, next, i == s.history_tap ? std::optional(color_history) : std::nullopt},
                   i, s);
        current = next;
      }
      out.filtered = current;
    }
  }

  add_composite(graph, pipelines, {out.filtered, in.albedo, in.hdr, in.display, in.counters}, s);
  return out;
}

}  // namespace asvgf::passes
