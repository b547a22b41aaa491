// denoiser/passes/composite.hpp: the `composite` pass (shaders/denoise/composite.comp): re-modulates the
// albedo and writes HDR radiance (RGBA32F or RGBA16F) and the tonemapped sRGB display image (RGBA8).
#pragma once

#include <optional>
#include <string>

#include "asvgf/compute_pass.hpp"
#include "asvgf/denoise_settings.hpp"
#include "asvgf/render_graph.hpp"
#include "denoiser/passes/local_mean.hpp"

namespace asvgf::passes {

struct CompositeResources {
  // read: any float format (filtered colour, or raw samples); with local_mean also an R32Uint image of
  // RGB9E5 colour (a last a-trous iteration's, atrous.hpp)
  graph::ResourceId illumination = 0;
  graph::ResourceId albedo = 0;    // read: a float format, or R32Uint RGB9E5 words (input_formats.hpp)
  graph::ResourceId hdr = 0;       // written: RGBA32F or RGBA16F (rounded to the nearest half)
  graph::ResourceId display = 0;   // written: RGBA8Unorm, sRGB-encoded
  graph::ResourceId counters = 0;  // read-written SanitizeCounters buffer: zeroed outputs
  // The filtered specular signal and its albedo, added (pathtrace's split signals).
  std::optional<graph::ResourceId> specular, specular_albedo;
  // The displayed colour's local-mean correction, applied here (one signal only): its box means,
  // with the window's blocks they were made for.
  std::optional<LocalMeanImages> local_mean;
};
// Whether the radiance image `hdr` is RGBA16F (else RGBA32F); throws std::invalid_argument, naming
// `caller` and the image, for any other format.
bool hdr_half(const graph::RenderGraph& graph, graph::ResourceId hdr, const std::string& caller);
// Adds "composite" (settings.exposure, settings.tonemap; the local-mean correction with r.local_mean).
graph::PassBuilder add_composite(graph::RenderGraph& graph, PipelineCache& pipelines, const CompositeResources& r,
                                 const DenoiseSettings& settings);

}  // namespace asvgf::passes
