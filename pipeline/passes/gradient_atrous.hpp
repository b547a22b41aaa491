// passes/gradient_atrous.hpp: the `gradient_atrous` pass (shaders/denoise/gradient_atrous.comp):
// one edge-aware a-trous iteration over (delta, Delta) at 1/3 resolution, step 2^iteration.
#pragma once

#include <string>

#include "graph/render_graph.hpp"
#include "passes/denoise_settings.hpp"

namespace asvgf::passes {

class GradientAtrousPass {
 public:
  struct Resources {
    graph::ResourceId gradient_in = 0;   // read: 1/3 res RGBA16F (delta, Delta)
    graph::ResourceId depth_normal = 0;  // read: full-res guide (RGBA32F)
    graph::ResourceId gradient_out = 0;  // written: 1/3 res RGBA16F
  };
  explicit GradientAtrousPass(hal::Device& device);
  ~GradientAtrousPass();
  GradientAtrousPass(const GradientAtrousPass&) = delete;
  GradientAtrousPass& operator=(const GradientAtrousPass&) = delete;

  // Adds "gradient_atrous.<iteration + 1>" with step 2^iteration (sigma_z, sigma_n from settings).
  graph::PassBuilder add(graph::RenderGraph& graph, const Resources& resources, int iteration,
                         const DenoiseSettings& settings) const;
  // Adds settings.gradient_iterations iterations on transient RGBA16F images named
  // "gradient.<i>"; returns the last output (`gradient` itself when there are none).
  graph::ResourceId add_iterations(graph::RenderGraph& graph, graph::ResourceId gradient, graph::ResourceId depth_normal,
                                   const DenoiseSettings& settings) const;

 private:
  hal::Device& device_;
  hal::PipelineHandle pipeline_;
};

}  // namespace asvgf::passes
