// frame/frame_graph.hpp: the A-SVGF frame as a render graph, for every method.
//
// Methods share one graph; a method is the set of passes it keeps:
//   raw        gbuffer, pathtrace, composite
//   ema        + temporal (constant alpha), no spatial filter
//   svgf       + variance and the a-trous iterations (constant alpha)
//   asvgf      + gradient_select, gradient, gradient_atrous (adaptive alpha)
//   reference  gbuffer, pathtrace at N spp, accumulate, composite
// Until the GPU passes land (issues 7 and 8), each pass dispatches a pipeline whose reflection is
// derived from its declared bindings: enough for the recording HAL to check the ordering of the
// real frame, not enough to render. FrameGraphBuilder::pass_specs() lists those bindings.
#pragma once

#include <deque>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "graph/render_graph.hpp"

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

  // Declares the frame; `scene` resources (acceleration structure, geometry buffer) are imported.
  graph::RenderGraph build(const FrameSettings& settings, hal::AccelHandle tlas, hal::BufferHandle geometry);
  const std::vector<PassSpec>& pass_specs() const { return specs_; }

 private:
  void add(graph::RenderGraph& g, PassSpec spec, std::uint32_t width, std::uint32_t height,
           std::string skip_reason = {});
  hal::PipelineHandle pipeline_for(const graph::RenderGraph& g, const PassSpec& spec);

  hal::Device& device_;
  std::vector<PassSpec> specs_;
  std::map<std::string, hal::PipelineHandle> pipelines_;
  // Storage behind the ShaderInfo views handed to the device.
  std::deque<std::string> names_;
  std::deque<std::vector<hal::ShaderBinding>> bindings_;
  std::deque<hal::ShaderInfo> shaders_;
};

}  // namespace asvgf::frame
