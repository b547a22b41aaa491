// frame/frame_graph.hpp: the A-SVGF frame as a render graph, for every method.
//
// Methods share one graph; a method is the set of passes it keeps:
//   raw        gbuffer, pathtrace, composite
//   ema        + temporal (constant alpha), no spatial filter
//   svgf       + variance and the a-trous iterations (constant alpha)
//   asvgf      + gradient_select, gradient, gradient_atrous (adaptive alpha)
//   reference  gbuffer, pathtrace at N spp, accumulate, composite
// gbuffer, gradient_clear, gradient_select, pathtrace and accumulate are the real GPU passes
// (passes/frame_passes.hpp). The denoiser passes that have not landed yet dispatch a pipeline whose
// reflection is derived from their declared bindings: enough for the recording HAL to check the
// ordering of the frame, not enough to render. FrameGraphBuilder::pass_specs() lists those.
#pragma once

#include <deque>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "graph/render_graph.hpp"
#include "passes/compute_pass.hpp"
#include "render/scene_gpu.hpp"

namespace asvgf::frame {

enum class Method { Raw, Ema, Svgf, Asvgf, Reference };
std::string_view to_string(Method method);
std::optional<Method> method_from_string(std::string_view name);
inline constexpr Method kAllMethods[] = {Method::Raw, Method::Ema, Method::Svgf, Method::Asvgf, Method::Reference};

struct FrameSettings {
  Method method = Method::Asvgf;
  std::uint32_t width = 128, height = 128;
  int atrous_iterations = 5;    // SVGF paper: 5
  int gradient_iterations = 3;  // Q2RTX: 3 at 1/3 resolution
  int history_tap = 0;          // which a-trous iteration's output feeds the colour history
  bool scene_moved = true;      // false: nothing moved since last frame, the gradient passes are left out
  bool debug_view = false;      // also produce the intermediate-buffer view (demo)
  std::uint32_t frame = 0;      // frame index: decorrelates random numbers
  std::uint32_t seed = 0;       // --seed
  std::uint32_t spp = 1;        // samples per pixel of the path tracer this frame
  std::uint32_t max_bounces = 4;
  bool accumulation_valid = false;  // reference: last frame's accumulation continues
};

// Images the frame writes its results to, owned by the caller and imported into the graph; the
// frame leaves them in CopySrc for readback.
struct FrameTargets {
  hal::ImageHandle hdr;      // RGBA32F linear radiance
  hal::State hdr_state = hal::State::Undefined;
  hal::ImageHandle display;  // RGBA8 tonemapped
  hal::State display_state = hal::State::Undefined;
};

// One binding of a pass: the shader binding name, the graph resource, how it is used.
struct PassBinding {
  std::string name;
  graph::ResourceId resource = 0;
  graph::Use use = graph::Use::ShaderRead;
  bool history = false;
  bool optional = false;
};
struct PassSpec {
  std::string name;
  std::vector<PassBinding> bindings;
};

class FrameGraphBuilder {
 public:
  explicit FrameGraphBuilder(hal::Device& device);
  ~FrameGraphBuilder();

  // Declares the frame over the scene's GPU buffers (imported) and the caller's output images.
  graph::RenderGraph build(const FrameSettings& settings, const render::SceneGpu& scene, const FrameTargets& targets);
  const std::vector<PassSpec>& pass_specs() const { return specs_; }

 private:
  void add(graph::RenderGraph& g, PassSpec spec, std::uint32_t width, std::uint32_t height,
           std::string skip_reason = {});
  hal::PipelineHandle pipeline_for(const graph::RenderGraph& g, const PassSpec& spec);

  hal::Device& device_;
  passes::PipelineCache pipelines_cache_;
  std::vector<PassSpec> specs_;
  std::map<std::string, hal::PipelineHandle> pipelines_;
  // Storage behind the ShaderInfo views handed to the device.
  std::deque<std::string> names_;
  std::deque<std::vector<hal::ShaderBinding>> bindings_;
  std::deque<hal::ShaderInfo> shaders_;
};

}  // namespace asvgf::frame
