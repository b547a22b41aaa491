// asvgf::passes::add_denoiser (include/asvgf/denoiser_graph.hpp): the method decides which passes
// are declared; settings only tune them.
#include "asvgf/denoiser_graph.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "denoiser/passes/atrous.hpp"
#include "denoiser/passes/composite.hpp"
#include "denoiser/passes/gradient.hpp"
#include "denoiser/passes/gradient_atrous.hpp"
#include "denoiser/passes/local_mean.hpp"
#include "denoiser/passes/temporal.hpp"
#include "denoiser/passes/variance.hpp"

namespace asvgf::passes {

namespace {

// How much of the chain runs: None composites the input as it is; Temporal is the EMA;
// Spatiotemporal adds variance and the a-trous iterations.
enum class Filter { None, Temporal, Spatiotemporal };

// One signal's temporal filter (and variance and a-trous iterations for Spatiotemporal), with its
// histories; resources and passes are named with `prefix`. With `composite`, a last a-trous
// iteration on packed texels also does the composite pass's work (`composited`).
struct Chain {
  graph::ResourceId filtered = 0, moments = 0, integrated = 0, variance = 0, color_history = 0;
  bool composited = false;
  // The tapped history's local-mean correction's block sums, whose temporal terms the displayed
  // colour's correction reads instead of summing the temporal result again.
  std::optional<graph::ResourceId> local_mean_sums;
  // The displayed colour's block sums, where the last a-trous iteration made them.
  std::optional<graph::ResourceId> display_sums;
  // The last iteration's result as RGB9E5 (R32Uint), for the composite's local-mean correction.
  std::optional<graph::ResourceId> filtered_rgb9e5;
};
Chain add_chain(graph::RenderGraph& graph, PipelineCache& pipelines, graph::ResourceId signal, graph::ResourceId albedo,
                const std::string& prefix, const GraphDenoiserInputs& in, std::optional<graph::ResourceId> gradient,
                const DenoiseSettings& s, Filter filter, std::optional<CompositeResources> composite,
                std::optional<graph::ResourceId> virtual_motion = std::nullopt, bool local_mean = false,
                bool rgb9e5_display = false) {
  using F = hal::Format;
  using graph::Lifetime;
  using graph::ResourceId;
  const auto& decl = graph.resource(signal);
  const std::uint32_t w = decl.width, h = decl.height;
  Chain c;
  const bool spatial = filter == Filter::Spatiotemporal && s.atrous_iterations > 0;
  // A spatial chain keeps its colour history and temporal result as RGB9E5 words (4 bytes a pixel
  // instead of 8, written once and read at few places: temporal.comp's COLOR_RGB9E5); the EMA's
  // result is its displayed colour, RGBA16F.
  const F color_format = spatial ? F::R32Uint : F::RGBA16F;
  c.color_history = graph.add_image(prefix + "color_history", w, h, color_format, Lifetime::Persistent);
  c.moments = graph.add_image(prefix + "moments", w, h, F::R32Uint, Lifetime::Persistent);  // pack_moments
  // Without a spatial filter, or with history_tap -1, the temporal result is itself next frame's
  // colour history (and no a-trous iteration writes one).
  c.integrated =
      spatial && s.history_tap >= 0 ? graph.add_image(prefix + "integrated", w, h, color_format) : c.color_history;
  add_temporal(graph, pipelines,
               {signal, virtual_motion.value_or(in.motion), in.depth_normal, c.color_history, c.moments, c.integrated,
                in.counters, gradient, prefix, virtual_motion.has_value()},
               s);
  c.filtered = c.integrated;
  c.variance = c.integrated;
  if (!spatial) return c;
  // Declared always: the variance debug view reads it. The first packed a-trous iteration
  // estimates the variance itself, so where only the chain reads, the graph leaves this pass out.
  ResourceId current = graph.add_image(prefix + "color_variance", w, h, F::RGBA16F);
  c.variance = current;
  add_variance(graph, pipelines, {c.integrated, c.moments, in.depth_normal, current, albedo, prefix}, s);
  const int k = local_mean ? local_mean_window(s, w, h) : 0;
  const LocalMeanBlocks blocks = local_mean_blocks(k);
  const std::uint64_t range = pipelines.device().capabilities().max_storage_buffer_range;
  const std::uint64_t max_storage_binding = range ? range : std::uint64_t{1} << 27;  // 0: not known
  std::optional<ResourceId> surface;  // the packed surface texels, once an iteration writes them
  // The history's correction's box means, for the next iteration, which applies it (below).
  // (A flag and an id, not an optional: GCC 12 at -O2 warns that the optional may be uninitialized.)
  bool history_correction_pending = false;
  ResourceId history_box_means = 0;
  for (int i = 0; i < s.atrous_iterations; ++i) {
    // Packed filter texels between the 5x5 kernel's iterations: two loads a tap, no decode
    // (denoiser/passes/atrous.hpp). The 3x3 box's 8 taps gain less than the wider texel costs (measured:
    // docs/performance.md). Images too where the buffer would exceed the device's largest storage binding (Vulkan,
    // OpenGL ES and WebGPU guarantee 2^27 bytes: 4K fits, 8K does not).
    const std::string name = prefix + "atrous." + std::to_string(i + 1);
    const std::uint64_t packed_bytes = std::uint64_t{w} * h * 8;
    const bool packed =
        i + 1 < s.atrous_iterations && s.kernel == AtrousKernel::B3Spline && packed_bytes <= max_storage_binding;
    const ResourceId next = packed ? graph.add_buffer(name, packed_bytes) : graph.add_image(name, w, h, F::RGBA16F);
    const bool first_packed = packed && !surface;
    if (first_packed) surface = graph.add_buffer(prefix + "filter_surface", packed_bytes);
    // With the local-mean correction the tapped history is corrected too (after this iteration):
    // uncorrected, the filter's energy loss would feed back through the history into the temporal
    // result that the displayed colour is corrected toward.
    const bool tap = i == s.history_tap;
    // Where the tapped iteration is the first packed one and the next a packed middle one, that next
    // iteration writes the corrected history itself (atrous.hpp's HistoryCorrection): the tapped
    // result goes to no image of its own.
    const bool history_corrected_next = local_mean && tap && first_packed && i + 2 < s.atrous_iterations;
    const std::optional<ResourceId> history =
        !tap || history_corrected_next
            ? std::nullopt
            : std::optional(local_mean ? graph.add_image(prefix + "color_history_filtered", w, h, color_format)
                                       : c.color_history);
    const bool last_packed = i + 1 == s.atrous_iterations && surface && !packed;
    // The local mean's block sums from the iteration whose result they sum, where it can (atrous.hpp):
    // the history's from the first packed iteration, the displayed colour's from a packed-in last one
    // (with the history's temporal terms). Elsewhere local_mean.hpp's blocks pass sums them.
    std::optional<AtrousResources::LocalMeanSums> sums;
    if (local_mean && tap && first_packed)
      sums = {add_local_mean_sums_image(graph, prefix + "local_mean.history", w, h, k), std::nullopt, blocks.block};
    else if (local_mean && !tap && last_packed && c.local_mean_sums)
      sums = {add_local_mean_sums_image(graph, prefix + "local_mean", w, h, k), c.local_mean_sums, blocks.block};
    if (last_packed && sums && rgb9e5_display) {
      // The composite reads the result as RGB9E5 (4 bytes a pixel written and read instead of 8); the
      // RGBA16F result stays declared, by a twin that runs only where something reads it.
      AtrousResources r{current,      in.depth_normal, graph.add_image(name + ".rgb9e5", w, h, F::R32Uint),
                        std::nullopt, prefix,          surface};
      r.local_mean_sums = sums;
      add_atrous(graph, pipelines, r, i, s);
      c.filtered_rgb9e5 = r.color_out;
      AtrousResources twin{current, in.depth_normal, next, std::nullopt, prefix, surface};
      twin.name_suffix = ".rgba16f";
      add_atrous(graph, pipelines, twin, i, s);
    } else if (last_packed && composite) {
      // The filtered image is still declared, by an iteration without the history tap that only
      // runs where something reads it (the tests' readbacks): the graph leaves it out otherwise.
      add_atrous(graph, pipelines, {current, in.depth_normal, next, history, prefix, surface, {}, composite}, i, s);
      c.composited = true;
      add_atrous(graph, pipelines, {current, in.depth_normal, next, std::nullopt, prefix, surface}, i, s);
    } else {
      AtrousResources r{first_packed ? c.integrated : current,
                        in.depth_normal,
                        next,
                        history,
                        prefix,
                        surface,
                        first_packed ? std::optional(VarianceEstimateInputs{c.moments, albedo}) : std::nullopt};
      r.local_mean_sums = sums;
      if (history_correction_pending) {
        r.color_history = c.color_history;
        r.corrects_history = {history_box_means, blocks.block, blocks.radius};
        history_correction_pending = false;
      }
      add_atrous(graph, pipelines, r, i, s);
    }
    if (tap && local_mean) {
      LocalMeanResources r{c.integrated, history.value_or(c.color_history), c.color_history,
                           prefix + "local_mean.history", false};
      if (sums) r.block_sums = sums->block_sums;
      r.apply_pass = !history_corrected_next;
      const LocalMeanImages images = add_local_mean(graph, pipelines, r, s);
      c.local_mean_sums = images.block_sums;
      if (history_corrected_next) {
        history_correction_pending = true;
        history_box_means = images.box_means;
      }
    } else if (sums) {
      c.display_sums = sums->block_sums;
    }
    current = next;
  }
  c.filtered = current;
  return c;
}

}  // namespace

GraphDenoiserOutputs add_denoiser(graph::RenderGraph& graph, PipelineCache& pipelines, const GraphDenoiserInputs& in,
                                  const DenoiseSettings& s, std::optional<DenoiseMethod> method) {
  using F = hal::Format;
  using graph::Lifetime;
  using graph::ResourceId;
  const auto& decl = graph.resource(in.illumination);
  const std::uint32_t w = decl.width, h = decl.height;
  if (in.specular && !in.specular_albedo)
    throw std::invalid_argument("add_denoiser: a specular signal needs its specular_albedo");
  GraphDenoiserOutputs out;
  out.filtered = in.illumination;
  const Filter filter = !method                        ? Filter::None
                        : method == DenoiseMethod::Ema ? Filter::Temporal
                                                       : Filter::Spatiotemporal;

  const bool adaptive = method == DenoiseMethod::Asvgf;
  const bool reprojected = adaptive && s.gradient_source == GradientSource::Reprojected;
  if (reprojected || (adaptive && in.gradient_prev)) {
    // Re-shaded: declared on still frames too, so that dump() shows them left out with the reason.
    // Reprojected: runs on every frame, still ones too: its luminance is the next frame's history.
    const bool skip = !reprojected && !in.gradient_skip_reason.empty();
    const std::uint32_t gw = (w + 2) / 3, gh = (h + 2) / 3;  // one stratum per 3x3 pixels
    // With l_cur given, the first a-trous iteration computes the gradient from the samples itself.
    const bool samples_in = !reprojected && in.gradient_current_given && s.gradient_iterations > 0;
    ResourceId current = samples_in ? *in.gradient_prev : graph.add_image("gradient", gw, gh, F::RGBA16F);
    if (reprojected) {
      const ResourceId luminance = graph.add_image("noisy_luminance", w, h, F::R32F, Lifetime::Persistent);
      add_gradient_reprojected(graph, pipelines, {in.illumination, in.motion, in.depth_normal, luminance, current});
    } else if (!samples_in) {
      add_gradient(graph, pipelines,
                   {in.illumination, *in.gradient_prev, current, in.specular.has_value(), in.gradient_current_given})
          .skip_if(skip, in.gradient_skip_reason);
    }
    // Several iterations read depth_normal's strata centres from an image of their own.
    const std::optional<ResourceId> strata_guide =
        s.gradient_iterations > 1 ? std::optional(graph.add_image("gradient_guide", gw, gh, F::RGBA16Uint))
                                  : std::nullopt;
    for (int i = 0; i < s.gradient_iterations; ++i) {
      const ResourceId next = graph.add_image("gradient." + std::to_string(i + 1), gw, gh, F::RGBA16F);
      add_gradient_atrous(graph, pipelines,
                          {current, in.depth_normal, next, i == 0 ? strata_guide : std::nullopt,
                           i > 0 ? strata_guide : std::nullopt, samples_in && i == 0, in.specular.has_value()},
                          i, s)
          .skip_if(skip, in.gradient_skip_reason);
      current = next;
    }
    if (!skip) out.gradient = current;
  }

  Chain diffuse;
  // Where the composite applies the displayed colour's local-mean correction itself: the windows'
  // means, and the uncorrected colour it reads.
  std::optional<LocalMeanImages> display_local_mean;
  ResourceId composite_input = 0;
  if (filter != Filter::None) {
    // The local-mean correction reads the last iteration's output (s.local_mean, denoiser/passes/local_mean.hpp).
    const bool local_mean =
        local_mean_window(s, w, h) > 0 && filter == Filter::Spatiotemporal && s.atrous_iterations > 0;
    // One signal: its last packed a-trous iteration composites (but not what is corrected after it).
    const std::optional<CompositeResources> composite =
        in.specular || local_mean
            ? std::nullopt
            : std::optional(CompositeResources{0, in.albedo, in.hdr, in.display, in.counters, {}, {}});
    // With one signal, the composite applies the correction to the last iteration's RGB9E5 result.
    diffuse = add_chain(graph, pipelines, in.illumination, in.albedo, "", in, out.gradient, s, filter, composite,
                        std::nullopt, local_mean, local_mean && !in.specular);
    if (local_mean) {
      // The corrected colour's image is declared for what reads it (the tests, the debug views);
      // with one signal the composite applies the correction itself and nothing else does.
      const ResourceId corrected = graph.add_image("local_mean_corrected", w, h, F::RGBA16F);
      const LocalMeanImages images =
          add_local_mean(graph, pipelines,
                         {diffuse.integrated, diffuse.filtered, corrected, "local_mean", true,
                          // the temporal terms are in the last iteration's sums where it made them
                          diffuse.display_sums ? std::nullopt : diffuse.local_mean_sums, diffuse.display_sums},
                         s);
      if (!in.specular) display_local_mean = images;
      composite_input = diffuse.filtered_rgb9e5.value_or(diffuse.filtered);
      diffuse.filtered = corrected;
    }
    out.filtered = diffuse.filtered;
    out.moments = diffuse.moments;
    out.integrated = diffuse.integrated;
    out.variance = diffuse.variance;
    out.color_history = diffuse.color_history;
    if (in.specular) {
      DenoiseSettings specular = s;
      specular.atrous_iterations = s.specular_atrous_iterations;
      specular.history_tap = std::min(s.history_tap, std::max(0, s.specular_atrous_iterations - 1));
      if (s.specular_sigma_l > 0.0f) specular.sigma_l = s.specular_sigma_l;
      if (s.specular_alpha > 0.0f) specular.alpha = s.specular_alpha;
      out.specular = add_chain(graph, pipelines, *in.specular, *in.specular_albedo, "specular.", in, out.gradient,
                               specular, filter, std::nullopt, in.specular_motion)
                         .filtered;
    }
  } else {
    out.specular = in.specular;
  }

  if (!diffuse.composited)
    add_composite(graph, pipelines,
                  {display_local_mean ? composite_input : out.filtered, in.albedo, in.hdr, in.display, in.counters,
                   out.specular, out.specular ? in.specular_albedo : std::nullopt, display_local_mean},
                  s);
  return out;
}

}  // namespace asvgf::passes
