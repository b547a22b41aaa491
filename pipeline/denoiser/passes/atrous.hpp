// denoiser/passes/atrous.hpp: the `atrous` pass (shaders/denoise/atrous.comp): one iteration of the
// edge-avoiding a-trous wavelet filter, step 2^iteration, optionally also writing the colour history.
#pragma once

#include <optional>
#include <string>

#include "asvgf/compute_pass.hpp"
#include "asvgf/denoise_settings.hpp"
#include "asvgf/render_graph.hpp"

namespace asvgf::passes {

struct AtrousResources {
  // color_in and color_out: RGBA16F images (rgb, variance) or storage buffers of packed filter
  // texels (16 bytes a pixel, in rows; shaders/common/filter_texel.glsl), which carry the surface too
  // and which the iterations between a chain's first and last pass on. A buffer out from an image in
  // is the first iteration only (it reads a shared-memory tile that needs step 1).
  graph::ResourceId color_in = 0;                  // read
  graph::ResourceId depth_normal = 0;              // read (not by packed-in iterations): RGBA32F
  graph::ResourceId color_out = 0;                 // written
  std::optional<graph::ResourceId> color_history;  // also written (persistent RGBA16F) at the history tap
  std::string prefix;                              // of the pass name: "specular." for the second signal
  // R32F, depth_normal's depth gradient, which the packed texel has no room for: written by the
  // first packed iteration, read by every packed-in one instead of depth_normal.
  std::optional<graph::ResourceId> depth_gradient;
};
// Adds "<prefix>atrous.<iteration + 1>" with step 2^iteration and the settings' kernel and sigmas.
// The dispatch covers depth_normal's size. Throws std::invalid_argument for a buffer out from an
// image in at an iteration other than 0, for colour images of another size or buffers smaller
// than 16 bytes a pixel, and for a packed iteration without depth_gradient.
graph::PassBuilder add_atrous(graph::RenderGraph& graph, PipelineCache& pipelines, const AtrousResources& r,
                              int iteration, const DenoiseSettings& settings);

}  // namespace asvgf::passes
