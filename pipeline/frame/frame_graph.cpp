// Declaring the passes of one frame for each method.
#include "frame/frame_graph.hpp"

namespace asvgf::frame {

using graph::Lifetime;
using graph::ResourceId;

std::string_view to_string(Method method) {
  switch (method) {
    case Method::Raw: return "raw";
    case Method::Ema: return "ema";
    case Method::Svgf: return "svgf";
    case Method::Asvgf: return "asvgf";
    case Method::Reference: return "reference";
  }
  return "?";
}

std::optional<Method> method_from_string(std::string_view name) {
  for (Method m : kAllMethods)
    if (to_string(m) == name) return m;
  return std::nullopt;
}

FrameGraphBuilder::FrameGraphBuilder(hal::Device& device)
    : pipelines_(device),
      temporal_(device),
      variance_(device),
      atrous_(device),
      gradient_(device),
      gradient_atrous_(device),
      composite_(device),
      counters_(device) {}

graph::RenderGraph FrameGraphBuilder::build(const FrameSettings& s, const render::SceneGpu& scene_gpu,
                                            const FrameTargets& targets) {
  graph::RenderGraph g;
  const std::uint32_t w = s.width, h = s.height;
  const std::uint32_t gw = (w + 2) / 3, gh = (h + 2) / 3;  // one gradient sample per 3x3 stratum
  using F = hal::Format;
  passes::DenoiseSettings denoise = s.denoise;
  denoise.adaptive = s.method == Method::Asvgf;

  const passes::SceneInputs scene = passes::import_scene(g, scene_gpu, w, h);
  const ResourceId hdr = g.import("hdr", targets.hdr, targets.hdr_state, w, h);
  const ResourceId display = g.import("display", targets.display, targets.display_state, w, h);
  const ResourceId rays = g.import("ray_counter", targets.ray_counter, targets.ray_counter_state);
  const ResourceId counters = counters_.import(g);
  g.output(rays, hal::State::CopySrc);
  // Persistent: read next frame as histories.
  const ResourceId vbuffer = g.add_image("visibility", w, h, F::RGBA32Uint, Lifetime::Persistent);
  const ResourceId depth_normal = g.add_image("depth_normal", w, h, F::RGBA32F, Lifetime::Persistent);
  const ResourceId seeds = g.add_image("rng_seed", w, h, F::R32Uint, Lifetime::Persistent);
  const ResourceId illumination = g.add_image("illumination", w, h, F::RGBA32F, Lifetime::Persistent);
  // Transient.
  const ResourceId motion = g.add_image("motion", w, h, F::RGBA32F);  // xy used
  const ResourceId albedo = g.add_image("albedo", w, h, F::RGBA16F);

  passes::add_gbuffer(g, pipelines_, scene, {vbuffer, depth_normal, motion, albedo}, w, h);

  // A-SVGF's temporal gradient: forward-projected samples, then delta and Delta at 1/3 resolution.
  const std::string not_moved = "nothing in the scene, camera or lights moved since the last frame";
  const bool adaptive = s.method == Method::Asvgf;
  const bool gradients = adaptive && s.scene_moved;
  std::optional<ResourceId> gradient_seeds, gradient_final;
  ResourceId gradient_prev = 0;
  if (adaptive) {
    gradient_seeds = g.add_image("gradient_seeds", w, h, F::RGBA32Uint);
    gradient_prev = g.add_image("gradient_prev_luminance", gw, gh, F::RGBA32F);  // xy used
    const ResourceId claims = g.add_buffer("gradient_claims", std::uint64_t(gw) * gh * 4);
    passes::add_gradient_select(g, pipelines_, scene,
                                {vbuffer, seeds, illumination, depth_normal, claims, *gradient_seeds, gradient_prev},
                                s.frame, w, h, gradients ? "" : not_moved);
  }
  passes::add_pathtrace(g, pipelines_, scene, vbuffer, gradients ? gradient_seeds : std::nullopt, illumination, seeds,
                        rays, {s.frame, s.seed, s.max_bounces, s.spp}, w, h);
  if (adaptive) {
    // Declared on still frames too, so that dump() shows them left out with the reason.
    ResourceId current = g.add_image("gradient", gw, gh, F::RGBA16F);
    gradient_.add(g, {illumination, gradient_prev, current}).skip_if(!gradients, not_moved);
    for (int i = 0; i < denoise.gradient_iterations; ++i) {
      const ResourceId next = g.add_image("gradient." + std::to_string(i + 1), gw, gh, F::RGBA16F);
      gradient_atrous_.add(g, {current, depth_normal, next}, i, denoise).skip_if(!gradients, not_moved);
      current = next;
    }
    if (gradients) gradient_final = current;
  }

  ResourceId filtered = illumination;
  std::optional<ResourceId> shown_moments, shown_variance;  // for the debug view
  if (s.method == Method::Reference) {
    const ResourceId accumulation = g.add_image("accumulation", w, h, F::RGBA32F, Lifetime::Persistent);
    passes::add_accumulate(g, pipelines_, illumination, accumulation, s.accumulation_valid, w, h);
    filtered = accumulation;
  } else if (s.method != Method::Raw) {
    const ResourceId color_history = g.add_image("color_history", w, h, F::RGBA16F, Lifetime::Persistent);
    const ResourceId moments = g.add_image("moments", w, h, F::RGBA32F, Lifetime::Persistent);
    const bool spatial = s.method != Method::Ema && denoise.atrous_iterations > 0;
    // Without a spatial filter the temporal result is itself next frame's colour history.
    const ResourceId integrated = spatial ? g.add_image("integrated", w, h, F::RGBA16F) : color_history;
    temporal_.add(g, {illumination, motion, depth_normal, color_history, moments, integrated, counters,
                      gradient_final},
                  denoise);
    filtered = integrated;
    shown_moments = moments;
    shown_variance = integrated;
    if (spatial) {
      ResourceId current = g.add_image("color_variance", w, h, F::RGBA16F);
      shown_variance = current;
      variance_.add(g, {integrated, moments, depth_normal, current}, denoise);
      for (int i = 0; i < denoise.atrous_iterations; ++i) {
        const ResourceId next = g.add_image("atrous." + std::to_string(i + 1), w, h, F::RGBA16F);
        atrous_.add(g, {current, depth_normal, next, i == denoise.history_tap ? std::optional(color_history) : std::nullopt},
                    i, denoise);
        current = next;
      }
      filtered = current;
    }
  }

  composite_.add(g, {filtered, albedo, hdr, display, counters}, denoise);
  g.output(hdr, hal::State::CopySrc);
  g.output(display, hal::State::CopySrc);

  // The intermediate-buffer view is an output only when asked for; otherwise it is culled.
  const ResourceId debug = targets.debug ? g.import("debug_view", targets.debug, targets.debug_state, w, h)
                                         : g.add_image("debug_view", w, h, F::RGBA8Unorm);
  passes::add_debug_view(g, pipelines_,
                         {depth_normal, motion, albedo, illumination, debug, gradient_final, shown_moments,
                          shown_variance, denoise.alpha, denoise.history_cap},
                         s.debug_view.value_or(passes::DebugView::Normals), w, h);
  if (s.debug_view) g.output(debug, hal::State::CopySrc);
  return g;
}

}  // namespace asvgf::frame
