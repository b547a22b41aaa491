// renderer/frame_graph.hpp: the A-SVGF frame as a render graph, for every method.
//
// Methods share one graph; a method is the set of passes it keeps:
//   raw        gbuffer, pathtrace, composite
//   ema        + temporal (constant alpha), no spatial filter
//   svgf       + variance and the a-trous iterations (constant alpha)
//   asvgf      + gradient_clear, gradient_select, gradient, gradient_atrous (adaptive alpha)
//   reference  gbuffer, pathtrace at N spp, accumulate, composite
// Passes the frame does not need are left out with a reason (dump() shows them): the gradient
// passes when nothing moved since the last frame, the debug view when nobody shows it.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "asvgf/denoiser_graph.hpp"
#include "asvgf/render_graph.hpp"
#include "renderer/render_passes.hpp"
#include "renderer/scene_gpu.hpp"

namespace asvgf::frame {

// What the frame shows: the noisy samples (raw), one of the denoiser's methods, or the accumulated
// ground truth (reference).
enum class Method { Raw, Ema, Svgf, Asvgf, Reference };
// The denoiser's method behind `method`; nothing for raw and reference (no filter).
std::optional<DenoiseMethod> denoise_method(Method method);
// The radiance image's format: RGBA16F for the methods whose histories are half floats (ema, svgf,
// asvgf: their radiance is within half float's range), RGBA32F for raw and reference, unclamped.
hal::Format hdr_format(Method method);
std::string_view to_string(Method method);
std::optional<Method> method_from_string(std::string_view name);
inline constexpr Method kAllMethods[] = {Method::Raw, Method::Ema, Method::Svgf, Method::Asvgf, Method::Reference};

// What a run chooses once: the same for every frame (render::RenderSettings extends it).
struct FrameConfig {
  Method method = Method::Asvgf;
  std::uint32_t width = 128, height = 128;
  std::uint32_t spp = 1;  // samples per pixel (reference: of each frame; FrameSettings: of this batch)
  std::uint32_t max_bounces = 4;
  std::uint32_t seed = 0;  // --seed
  DenoiseSettings denoise;
  std::optional<passes::DebugView> debug_view;  // also produce this intermediate-buffer view (demo)
  // False (--no-demodulation): the denoiser filters radiance with the albedo in it, not
  // illumination = radiance / albedo (the seed's question: does filtering blur textures?).
  bool demodulate = true;
  // True (--specular-split): on scenes with glossy materials, filter the light the primary
  // surface's GGX lobe reflects apart from the rest, each with its own albedo and histories (ema,
  // svgf, asvgf with re-shaded gradients, no AOVs), the specular history reprojected through the
  // reflection's virtual point. Off by default: it pays when the camera moves and costs a little
  // when it does not (docs/quality.md).
  bool specular_split = false;
};

// One frame's graph: the run's choices and what changes from frame to frame.
struct FrameSettings : FrameConfig {
  bool scene_moved = true;          // false: nothing moved since last frame, the gradient passes are left out
  std::uint32_t frame = 0;          // frame index: decorrelates random numbers
  bool accumulation_valid = false;  // reference: last frame's accumulation continues
};

// Whether this frame selects and re-shades A-SVGF's gradient samples (the gradient passes run and
// AovTargets::gradient_samples is written): A-SVGF with re-shaded gradients, and something moved.
bool reshades_gradients(const FrameSettings& settings);

// One caller-owned image and the state it is in when the frame starts.
struct ImageTarget {
  hal::ImageHandle image;
  hal::State state = hal::State::Undefined;
};
// `asvgf render --aovs`: the denoiser's inputs in the public API's conventions
// (include/asvgf/denoiser.hpp), all RGBA32F and left in CopySrc. gradient_samples (ceil(w/3) x
// ceil(h/3)) is written only on frames where the gradient passes run (A-SVGF, something moved).
struct AovTargets {
  ImageTarget illumination, albedo, normal, depth, motion, gradient_samples;
};

// Images the frame writes its results to, owned by the caller and imported into the graph; the
// frame leaves them in CopySrc for readback.
struct FrameTargets {
  hal::ImageHandle hdr;  // linear radiance, in hdr_format
  hal::State hdr_state = hal::State::Undefined;
  hal::Format hdr_format = hal::Format::RGBA32F;  // RGBA32F or RGBA16F
  hal::ImageHandle display;                       // RGBA8 tonemapped
  hal::State display_state = hal::State::Undefined;
  hal::ImageHandle debug;  // RGBA8, written when FrameSettings::debug_view is set
  hal::State debug_state = hal::State::Undefined;
  hal::BufferHandle ray_counter;  // >= 4 bytes, zeroed by the caller: the path tracer adds its rays
  hal::State ray_counter_state = hal::State::Undefined;
  std::optional<AovTargets> aovs;  // raw, ema, svgf, asvgf
};

class FrameGraphBuilder {
 public:
  explicit FrameGraphBuilder(hal::Device& device);

  // Declares the frame over the scene's GPU buffers (imported) and the caller's output images.
  // Throws hal::Error(InvalidUsage) when AOVs are asked of the reference method.
  graph::RenderGraph build(const FrameSettings& settings, const render::SceneGpu& scene, const FrameTargets& targets);
  // What the temporal and composite passes dropped, clamped and zeroed so far (waits for the device).
  SanitisedCounts dropped_samples() { return counters_.read(); }

 private:
  passes::PipelineCache pipelines_;
  passes::SanitizeCounters counters_;
};

}  // namespace asvgf::frame
