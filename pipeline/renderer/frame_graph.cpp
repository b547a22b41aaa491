// Declaring the passes of one frame for each method.
#include "renderer/frame_graph.hpp"

#include "hal/error.hpp"
#include "renderer/aov_passes.hpp"

namespace asvgf::frame {

namespace {
constexpr std::uint64_t kRayCounterSize = 4;  // pathtrace.comp's one uint RayCounter.count
}  // namespace

using graph::Lifetime;
using graph::ResourceId;

std::string_view to_string(Method method) {
  switch (method) {
    case Method::Raw:
      return "raw";
    case Method::Ema:
      return "ema";
    case Method::Svgf:
      return "svgf";
    case Method::Asvgf:
      return "asvgf";
    case Method::Reference:
      return "reference";
  }
  return "?";
}

std::optional<DenoiseMethod> denoise_method(Method method) {
  switch (method) {
    case Method::Ema:
      return DenoiseMethod::Ema;
    case Method::Svgf:
      return DenoiseMethod::Svgf;
    case Method::Asvgf:
      return DenoiseMethod::Asvgf;
    case Method::Raw:
    case Method::Reference:
      break;
  }
  return std::nullopt;
}

hal::Format hdr_format(Method method) {
  return denoise_method(method) ? hal::Format::RGBA16F : hal::Format::RGBA32F;
}

std::optional<Method> method_from_string(std::string_view name) {
  for (Method m : kAllMethods)
    if (to_string(m) == name) return m;
  return std::nullopt;
}

bool reshades_gradients(const FrameSettings& s) {
  const std::optional<DenoiseMethod> method = denoise_method(s.method);
  return method && asvgf::reshades_gradients(*method, s.denoise) && s.scene_moved;
}

FrameGraphBuilder::FrameGraphBuilder(hal::Device& device) : pipelines_(device), counters_(device) {}

graph::RenderGraph FrameGraphBuilder::build(const FrameSettings& s, const render::SceneGpu& scene_gpu,
                                            const FrameTargets& targets) {
  graph::RenderGraph g;
  const std::uint32_t w = s.width, h = s.height;
  const std::uint32_t gw = (w + 2) / 3, gh = (h + 2) / 3;  // one gradient sample per 3x3 stratum
  using F = hal::Format;
  const DenoiseSettings& denoise = s.denoise;
  const std::optional<DenoiseMethod> method = denoise_method(s.method);

  const passes::SceneInputs scene = passes::import_scene(g, scene_gpu, w, h);
  const ResourceId hdr = g.import("hdr", targets.hdr, targets.hdr_state, w, h, targets.hdr_format);
  const ResourceId display = g.import("display", targets.display, targets.display_state, w, h, F::RGBA8Unorm);
  const ResourceId rays =
      g.import_buffer("ray_counter", targets.ray_counter, targets.ray_counter_state, kRayCounterSize);
  const ResourceId counters = counters_.import(g);
  g.output(rays, hal::State::CopySrc);
  // Persistent: read next frame as histories.
  const ResourceId depth_normal = g.add_image("depth_normal", w, h, F::RGBA16Uint, Lifetime::Persistent);
  const ResourceId candidates = passes::add_gradient_candidates_image(g, w, h);
  // Transient.
  // The filtering methods' samples in half floats (pathtrace.comp: what the denoiser keeps of them);
  // raw output and the reference unclamped.
  const bool full_range = !method;
  const ResourceId illumination = g.add_image("illumination", w, h, full_range ? F::RGBA32F : F::RGBA16F);
  const ResourceId vbuffer = g.add_image("visibility", w, h, F::RGBA32Uint);
  const ResourceId motion = g.add_image("motion", w, h, F::R32Uint);  // x, y as halves (shaders/common/motion.glsl)
  // RGB9E5 words: what the path tracer divides by (shaders/common/albedo.glsl)
  const ResourceId albedo = g.add_image("albedo", w, h, F::R32Uint);
  // Two signals only where a second chain has something to filter and every consumer of the
  // illumination knows the split: the reprojected gradient and the AOVs read one signal.
  const bool split = s.specular_split && scene_gpu.glossy() && method &&
                     !(method == DenoiseMethod::Asvgf && denoise.gradient_source == GradientSource::Reprojected) &&
                     !targets.aovs;
  std::optional<ResourceId> specular, specular_albedo;
  if (split) {
    specular = g.add_image("specular", w, h, F::RGBA32F);
    specular_albedo = g.add_image("specular_albedo", w, h, F::RGBA16F);
  }

  passes::add_gbuffer(g, pipelines_, scene, {vbuffer, depth_normal, motion, albedo, split}, w, h, s.demodulate);

  // A-SVGF's temporal gradient: forward-projected samples, then delta and Delta at 1/3 resolution.
  const std::string not_moved = "nothing in the scene, camera or lights moved since the last frame";
  // Re-shaded samples only for GradientSource::Reshaded; Reprojected estimates inside add_denoiser.
  const bool reshaded = method && asvgf::reshades_gradients(*method, denoise);
  const bool gradients = reshades_gradients(s);
  const passes::PathtraceSettings tracing{s.frame, s.seed, s.max_bounces, s.spp, s.demodulate, full_range};
  std::optional<passes::CarriedSampleTargets> carried;
  if (reshaded) {
    const passes::CarriedSamples resolved{g.add_image("gradient_seeds", gw, gh, F::RGBA32Uint),
                                          g.add_image("gradient_prev_luminance", gw, gh, F::RGBA32F)};  // xy used
    const ResourceId claims = g.add_buffer("gradient_claims", std::uint64_t(gw) * gh * 4);
    passes::add_gradient_select(g, pipelines_, scene, {candidates, depth_normal, claims, resolved}, w, h,
                                gradients ? "" : not_moved);
    // The carried samples traced apart from the pixels: every pixel keeps a fresh sample.
    carried = {resolved, g.add_image("gradient_samples", gw, gh, F::RGBA32F), split, gradients ? "" : not_moved};
  }
  passes::add_pathtrace(
      g, pipelines_, scene, vbuffer, albedo, illumination, candidates, rays, tracing, w, h, "pathtrace",
      split ? std::optional(passes::SpecularTargets{*specular, *specular_albedo}) : std::nullopt, carried);
  const ResourceId gradient_samples = carried ? carried->gradient_samples : 0;
  std::optional<ResourceId> specular_motion;
  if (split) {
    specular_motion = g.add_image("specular_motion", w, h, F::RGBA32F);
    passes::add_specular_motion(g, pipelines_, scene, depth_normal, motion, *specular, *specular_motion, w, h);
  }
  ResourceId input = illumination;
  if (s.method == Method::Reference) {
    const ResourceId accumulation = g.add_image("accumulation", w, h, F::RGBA32F, Lifetime::Persistent);
    passes::add_accumulate(g, pipelines_, illumination, accumulation, s.accumulation_valid, w, h);
    input = accumulation;
  }
  const passes::GraphDenoiserOutputs denoised =
      passes::add_denoiser(g, pipelines_,
                           {input, motion, depth_normal, albedo, counters, hdr, display,
                            reshaded ? std::optional(gradient_samples) : std::nullopt, gradients ? "" : not_moved, true,
                            specular, specular_albedo, specular_motion},
                           denoise, method);
  g.output(hdr, hal::State::CopySrc);
  g.output(display, hal::State::CopySrc);

  // The intermediate-buffer view is an output only when asked for; otherwise it is culled.
  const ResourceId debug = targets.debug
                               ? g.import("debug_view", targets.debug, targets.debug_state, w, h, F::RGBA8Unorm)
                               : g.add_image("debug_view", w, h, F::RGBA8Unorm);
  passes::add_debug_view(g, pipelines_,
                         {depth_normal, motion, albedo, illumination, debug, denoised.gradient, denoised.moments,
                          denoised.variance, denoise},
                         s.debug_view.value_or(passes::DebugView::Normals), w, h);
  if (s.debug_view) g.output(debug, hal::State::CopySrc);

  if (targets.aovs) {
    if (s.method == Method::Reference)
      throw hal::Error(hal::ErrorKind::InvalidUsage, "frame AOVs",
                       "the reference method has no denoiser inputs to export");
    const AovTargets& a = *targets.aovs;
    auto import = [&](const char* name, const ImageTarget& t, std::uint32_t iw, std::uint32_t ih) {
      const ResourceId id = g.import(name, t.image, t.state, iw, ih, F::RGBA32F);
      g.output(id, hal::State::CopySrc);
      return id;
    };
    passes::add_export_aovs(g, pipelines_,
                            {depth_normal, albedo, import("aov.depth", a.depth, w, h),
                             import("aov.normal", a.normal, w, h), import("aov.albedo", a.albedo, w, h)});
    passes::add_image_widen(g, pipelines_, "aov_illumination", illumination,
                            import("aov.illumination", a.illumination, w, h));
    passes::add_image_widen(g, pipelines_, "aov_motion", motion, import("aov.motion", a.motion, w, h));
    if (gradients)
      passes::add_image_copy(g, "aov_gradient_samples", gradient_samples,
                             import("aov.gradient_samples", a.gradient_samples, gw, gh));
  }
  return g;
}

}  // namespace asvgf::frame
