// passes/atrous.hpp: the `atrous` pass (shaders/denoise/atrous.comp): one iteration of the
// edge-avoiding a-trous wavelet filter, step 2^iteration, optionally also writing the colour history.
#pragma once

#include <optional>

#include "graph/render_graph.hpp"
#include "passes/denoise_settings.hpp"

namespace asvgf::passes {

class AtrousPass {
 public:
  struct Resources {
    graph::ResourceId color_in = 0;      // read: RGBA16F (rgb, variance)
    graph::ResourceId depth_normal = 0;  // read: RGBA32F
    graph::ResourceId color_out = 0;     // written: RGBA16F (rgb, variance)
    std::optional<graph::ResourceId> color_history;  // also written (persistent RGBA16F) at the history tap
  };
  explicit AtrousPass(hal::Device& device);
  ~AtrousPass();
  AtrousPass(const AtrousPass&) = delete;
  AtrousPass& operator=(const AtrousPass&) = delete;

  // Adds "atrous.<iteration + 1>" with step 2^iteration and the settings' kernel and sigmas.
  void add(graph::RenderGraph& graph, const Resources& resources, int iteration, const DenoiseSettings& settings) const;
  // Adds settings.atrous_iterations iterations on transient RGBA16F images "atrous.<i>"; iteration
  // settings.history_tap also writes `color_history`. Returns the last output (`input` if none).
  graph::ResourceId add_iterations(graph::RenderGraph& graph, graph::ResourceId input, graph::ResourceId depth_normal,
                                   graph::ResourceId color_history, const DenoiseSettings& settings) const;

 private:
  hal::Device& device_;
  hal::PipelineHandle plain_, history_;
};

}  // namespace asvgf::passes
