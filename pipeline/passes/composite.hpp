// passes/composite.hpp: the `composite` pass (shaders/denoise/composite.comp): re-modulates the
// albedo and writes HDR radiance (RGBA32F) and the tonemapped sRGB display image (RGBA8).
#pragma once

#include "graph/render_graph.hpp"
#include "passes/denoise_settings.hpp"

namespace asvgf::passes {

class CompositePass {
 public:
  struct Resources {
    graph::ResourceId illumination = 0;  // read: any float format (filtered colour, or raw samples)
    graph::ResourceId albedo = 0;        // read: RGBA16F
    graph::ResourceId hdr = 0;           // written: RGBA32F
    graph::ResourceId display = 0;       // written: RGBA8Unorm, sRGB-encoded
    graph::ResourceId counters = 0;      // read-written SanitizeCounters buffer: zeroed outputs
  };
  explicit CompositePass(hal::Device& device);
  ~CompositePass();
  CompositePass(const CompositePass&) = delete;
  CompositePass& operator=(const CompositePass&) = delete;

  // Adds "composite" (settings.exposure, settings.tonemap).
  void add(graph::RenderGraph& graph, const Resources& resources, const DenoiseSettings& settings) const;

 private:
  hal::Device& device_;
  hal::PipelineHandle pipeline_;
};

}  // namespace asvgf::passes
