// renderer/render_passes.hpp: the passes that make the noisy input: scene import, gbuffer, path
// tracing, A-SVGF gradient-sample selection, and reference accumulation.
#pragma once

#include <optional>
#include <string>

#include "asvgf/compute_pass.hpp"
#include "asvgf/denoise_settings.hpp"
#include "renderer/scene_gpu.hpp"

namespace asvgf::passes {

// The scene's GPU buffers as imported graph resources (read-only in the frame).
struct SceneInputs {
  bool ray_query = false;
  graph::ResourceId tlas = 0, bvh_nodes = 0, bvh_triangles = 0;
  graph::ResourceId triangles = 0, previous_triangles = 0, materials = 0, lights = 0;
  graph::ResourceId triangle_uvs = 0, texels = 0;  // albedo textures
  std::uint32_t light_count = 0, sphere_count = 0;
  render::GpuCamera camera{}, previous_camera{};
};
SceneInputs import_scene(graph::RenderGraph& graph, const render::SceneGpu& scene, std::uint32_t width,
                         std::uint32_t height);

struct GbufferTargets {
  graph::ResourceId visibility, depth_normal, motion, albedo;
  bool diffuse_albedo_only = false;  // the diffuse lobe's albedo (pathtrace's split signals)
};
// `demodulate` false: the albedo written is 1 (the denoiser then filters radiance, albedo included).
void add_gbuffer(graph::RenderGraph& graph, PipelineCache& pipelines, const SceneInputs& scene,
                 const GbufferTargets& targets, std::uint32_t width, std::uint32_t height, bool demodulate = true);

struct SpecularTargets {
  graph::ResourceId signal, albedo;
};
struct PathtraceSettings {
  std::uint32_t frame = 0;        // decorrelates frames
  std::uint32_t seed = 0;         // --seed: the whole run's random numbers
  std::uint32_t max_bounces = 4;  // path length after the primary hit
  std::uint32_t spp = 1;          // samples per pixel in this dispatch
  bool demodulate = true;         // false: illumination is radiance (no division by the albedo)
  // The illumination's format: RGBA32F and unclamped (the methods that do not filter it: raw
  // output, the accumulated reference), else RGBA16F with finite samples clamped to [0, 65504]
  // (what the denoiser's temporal pass keeps of them anyway). Not with split signals or carried samples.
  bool full_range = false;
};
// What gradient_resolve writes for pathtrace_carried, one entry a 3x3 stratum: the carried seed and
// surface point (RGBA32Uint) and which pixel of the stratum gets them (gradient_prev, RGBA32F, .x
// last frame's luminance, .y: 0-8; -1, gradient_clear's, where no sample landed).
struct CarriedSamples {
  graph::ResourceId seeds, prev;
};
struct CarriedSampleTargets {
  CarriedSamples carried;              // read: gradient_resolve's
  graph::ResourceId gradient_samples;  // written: stratum-sized RGBA32F (l_prev, index, l_cur, 1; or 0 0)
  bool luminance_in_alpha = false;     // illumination holds pathtrace's split signals
  std::string skip_reason;             // not empty: nothing moved, no carried samples this frame
};
// Every pixel traces a fresh path of its own and divides it by the G-buffer's `albedo` word (R32Uint,
// RGB9E5), which the composite re-modulates by. `gradient_candidates` (RGBA32Uint, 2 x strata wide,
// strata high: add_gradient_candidates_image) gets, for each 3x3 stratum, the seed, surface point and
// luminance of the pixel that next frame's gradient_select projects
// (shaders/renderer/gradient_candidate.glsl).
// `specular` present: the split variant writes the specular signal (RGBA32F) and the GGX lobe's
// albedo (RGBA16F) there, and the diffuse signal, with the one-signal luminance in .a, to
// `illumination` (the gbuffer writes the diffuse albedo: GbufferTargets::diffuse_albedo_only).
// `carried` present: A-SVGF's re-shading. Each stratum with a carried sample traces it from last
// frame's surface point with last frame's seed and writes its luminance beside last frame's: the
// gradient samples the denoiser reads with GraphDenoiserInputs::gradient_current_given. Shaded
// apart from the pixel it lands in, whose own fresh sample goes into the histories; in the same
// dispatch (one signal), or with split signals in a pass of its own, "<name>_carried" (left out,
// with the skip reason, when there is one).
// `ray_counter`: a buffer whose first uint the pass adds the rays it traced to (closest-hit and
// shadow rays after the primary hit; the primary ray is the gbuffer's).
void add_pathtrace(graph::RenderGraph& graph, PipelineCache& pipelines, const SceneInputs& scene,
                   graph::ResourceId visibility, graph::ResourceId albedo, graph::ResourceId illumination,
                   graph::ResourceId gradient_candidates, graph::ResourceId ray_counter,
                   const PathtraceSettings& settings, std::uint32_t width, std::uint32_t height,
                   const std::string& name = "pathtrace", std::optional<SpecularTargets> specular = std::nullopt,
                   std::optional<CarriedSampleTargets> carried = std::nullopt);

// The image pathtrace writes the gradient's candidates to, for a width x height frame.
graph::ResourceId add_gradient_candidates_image(graph::RenderGraph& graph, std::uint32_t width, std::uint32_t height);

struct GradientSelectTargets {
  graph::ResourceId candidates;    // persistent: last frame's pathtrace's version is read
  graph::ResourceId depth_normal;  // this frame's
  graph::ResourceId claims;        // transient buffer, one uint per stratum
  CarriedSamples carried;          // stratum-sized
};
// Three passes: gradient_clear, gradient_select (bids), gradient_resolve (the winners write). Left
// out, with `skip_reason`, when not empty.
void add_gradient_select(graph::RenderGraph& graph, PipelineCache& pipelines, const SceneInputs& scene,
                         const GradientSelectTargets& targets, std::uint32_t width, std::uint32_t height,
                         const std::string& skip_reason);

// The specular history's motion through each pixel's reflection (shaders/renderer/specular_motion.comp):
// reads depth_normal, motion and pathtrace's split `specular` (a: the reflected ray's length), writes
// `target` (RGBA32F, xy).
void add_specular_motion(graph::RenderGraph& graph, PipelineCache& pipelines, const SceneInputs& scene,
                         graph::ResourceId depth_normal, graph::ResourceId motion, graph::ResourceId specular,
                         graph::ResourceId target, std::uint32_t width, std::uint32_t height);

// Running mean of `illumination` into the persistent `accumulation` (restarted when !history_valid).
void add_accumulate(graph::RenderGraph& graph, PipelineCache& pipelines, graph::ResourceId illumination,
                    graph::ResourceId accumulation, bool history_valid, std::uint32_t width, std::uint32_t height);

// The demo's view of an intermediate buffer.
// The last four are the denoiser's state as heat maps (shaders/renderer/debug_view.comp): A-SVGF's
// temporal gradient lambda, the temporal blend factor alpha, the luminance standard deviation that
// steers the a-trous filter, the history length; black where the method has no such buffer.
enum class DebugView : std::uint32_t {
  Normals = 0,
  Depth = 1,
  Motion = 2,
  Albedo = 3,
  NoisyInput = 4,
  Gradient = 5,
  Alpha = 6,
  Variance = 7,
  HistoryLength = 8
};
struct DebugViewInputs {
  graph::ResourceId depth_normal, motion, albedo, illumination, target;
  std::optional<graph::ResourceId> gradient;  // 1/3 res (delta^, Delta^), when the gradient ran this frame
  std::optional<graph::ResourceId> moments;   // temporal's output: R32Uint words (E[l], sqrt(Var[l]), n)
  std::optional<graph::ResourceId> variance;  // colour with variance in .a (variance pass, or temporal's)
  DenoiseSettings denoise;                    // what the temporal pass used (alpha, history cap)
};
void add_debug_view(graph::RenderGraph& graph, PipelineCache& pipelines, const DebugViewInputs& inputs, DebugView view,
                    std::uint32_t width, std::uint32_t height);

}  // namespace asvgf::passes
