// renderer/renderer.hpp: renders a scene's animation frame by frame with one method, on any HAL
// device, and hands back each frame's HDR and display images and its per-pass GPU times.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "asvgf/graph_runtime.hpp"
#include "renderer/frame_graph.hpp"
#include "renderer/scene/scene.hpp"
#include "renderer/scene_gpu.hpp"

namespace asvgf::render {

// The run's frame choices (method, size, spp, denoiser, ...) and how the renderer runs them.
struct RenderSettings : frame::FrameConfig {
  // Tracing variant: empty picks ray queries when the device has them, else the software BVH.
  std::optional<bool> ray_query;
  // Reference method: keep accumulating over frames while nothing moved (the demo's progressive
  // reference); false: every frame is its own estimate of `spp` samples.
  bool progressive = false;
  // False: render() returns only the size; the images stay on the GPU (display_image(), the demo).
  bool read_back = true;
  // Scene time per frame: 1 renders the animation at its keyframes' pace; smaller steps render it
  // in slow motion (the benchmark keeps a short move going for hundreds of frames).
  float time_per_frame = 1.0f;
  // Also read back the denoiser's inputs (FrameImages::aovs); not for the reference method.
  bool aovs = false;
};

// The denoiser's inputs of one frame in the public API's conventions (include/asvgf/denoiser.hpp),
// RGBA floats, rows top to bottom.
struct AovImages {
  std::vector<float> illumination, albedo, normal, depth, motion;
  // A-SVGF only (else empty), ceil(w/3) x ceil(h/3); on frames without gradient passes every
  // stratum says "no sample" (luminance 0, index -1).
  std::vector<float> gradient_samples;
  bool gradient_ran = false;
};

struct FrameImages {
  std::uint32_t width = 0, height = 0;
  std::vector<float> hdr;             // RGBA, linear radiance
  std::vector<std::uint8_t> display;  // RGBA8, tonemapped sRGB
  std::vector<std::uint8_t> debug;    // RGBA8 when a debug view was asked for
  std::optional<AovImages> aovs;      // RenderSettings::aovs
};

class Renderer {
 public:
  Renderer(hal::Device& device, const scene::Scene& scene, const RenderSettings& settings);
  ~Renderer();

  // Renders animation frame `frame` (frames must come in increasing order for histories to mean
  // anything; a jump back is treated as a camera cut).
  FrameImages render(int frame);
  // GPU milliseconds per pass of the last frame (all batches of a reference frame summed).
  const std::vector<PassTime>& timings() const { return timings_; }
  const graph::CompiledFrame& last_frame() const { return *last_compiled_; }
  SanitisedCounts dropped_samples() { return builder_.dropped_samples(); }
  const RenderSettings& settings() const { return settings_; }
  // Live changes between frames (the demo's keys): method, spp, max_bounces, denoiser settings,
  // debug view, progressive, read_back. Size, seed and tracing variant must stay (InvalidUsage).
  // A new method restarts the histories.
  void set_settings(const RenderSettings& settings);
  // The frame's output images, in State::CopySrc after render() (the caller may use them in
  // between, e.g. present them, as long as it returns them to CopySrc before the next render()).
  hal::ImageHandle display_image() const { return targets_.display; }
  hal::ImageHandle hdr_image() const { return targets_.hdr; }
  hal::ImageHandle debug_image() const { return targets_.debug; }  // empty before a debug view was asked for
  bool ray_query() const { return scene_gpu_.ray_query(); }
  // Rays traced in the last frame: one primary ray per pixel (gbuffer) plus the path tracer's.
  std::uint64_t rays_last_frame() const { return rays_last_frame_; }
  // Whether something in the scene, camera or lights moved between the last two frames (the
  // gradient passes ran).
  bool moved_last_frame() const { return moved_last_frame_; }
  // Samples per pixel actually traced per frame (the reference rounds up to equal batches).
  std::uint32_t spp_per_frame() const { return batches_ * batch_spp_; }

 private:
  hal::Device& device_;
  RenderSettings settings_;
  SceneGpu scene_gpu_;
  graph::GraphRuntime runtime_;
  frame::FrameGraphBuilder builder_;
  std::unique_ptr<hal::CommandList> commands_;
  frame::FrameTargets targets_;
  std::optional<graph::RenderGraph> last_graph_;
  std::optional<graph::CompiledFrame> last_compiled_;
  std::vector<PassTime> timings_;
  std::uint32_t batches_ = 1, batch_spp_ = 1;
  int last_frame_ = -1;
  void set_batches();
  void create_hdr_target();
  void create_aov_targets();
  void destroy_aov_targets();
  AovImages read_aovs(bool gradient_ran);
  std::uint64_t rays_last_frame_ = 0;
  bool moved_last_frame_ = false;
};

}  // namespace asvgf::render
