// denoiser/passes/composite.hpp: the `composite` pass (shaders/denoise/composite.comp): re-modulates the
// albedo and writes HDR radiance (RGBA32F) and the tonemapped sRGB display image (RGBA8).
#pragma once

#include <optional>

#include "asvgf/compute_pass.hpp"
#include "asvgf/denoise_settings.hpp"
#include "asvgf/render_graph.hpp"

namespace asvgf::passes {

struct CompositeResources {
  graph::ResourceId illumination = 0;  // read: any float format (filtered colour, or raw samples)
  graph::ResourceId albedo = 0;        // read: RGBA16F
  graph::ResourceId hdr = 0;           // written: RGBA32F
  graph::ResourceId display = 0;       // written: RGBA8Unorm, sRGB-encoded
  graph::ResourceId counters = 0;      // read-written SanitizeCounters buffer: zeroed outputs
  // The filtered specular signal and its albedo, added (pathtrace's split signals).
  std::optional<graph::ResourceId> specular, specular_albedo;
  // The displayed colour's local-mean correction, applied here (one signal only): the box means
  // of local_mean.hpp's LocalMeanImages, with local_mean_window(settings, ...)'s blocks.
  std::optional<graph::ResourceId> local_mean_box_means;
};
// Adds "composite" (settings.exposure, settings.tonemap; settings.local_mean with local_mean_box_means).
graph::PassBuilder add_composite(graph::RenderGraph& graph, PipelineCache& pipelines, const CompositeResources& r,
                                 const DenoiseSettings& settings);

}  // namespace asvgf::passes
