// denoiser/passes/atrous.hpp: the `atrous` pass (shaders/denoise/atrous.comp): one iteration of the
// edge-avoiding a-trous wavelet filter, step 2^iteration, optionally also writing the colour history.
#pragma once

#include <optional>
#include <string>

#include "asvgf/compute_pass.hpp"
#include "asvgf/denoise_settings.hpp"
#include "asvgf/render_graph.hpp"
#include "denoiser/passes/composite.hpp"

namespace asvgf::passes {

struct VarianceEstimateInputs {
  graph::ResourceId moments = 0;
  graph::ResourceId albedo = 0;  // a float format, or R32Uint RGB9E5 words (input_formats.hpp)
};

struct AtrousResources {
  // color_in and color_out: RGBA16F images (rgb, variance) or storage buffers of packed colour
  // texels (8 bytes a pixel, in rows; shaders/common/filter_texel.glsl), which the iterations between
  // a chain's first and last pass on, with the packed surface texels in `surface`. A buffer out from
  // an image in is the first iteration only (it reads a shared-memory tile that needs step 1): it
  // writes `surface`, and it estimates the variance itself: its color_in is the temporal pass's
  // output (R32Uint, RGB9E5 words) and it also reads `estimate` (the variance pass's other inputs).
  graph::ResourceId color_in = 0;      // read
  graph::ResourceId depth_normal = 0;  // read (not by packed-in iterations): RGBA16UI; the size
  // written (not with `composite`); a packed-in last iteration with local_mean_sums may write an R32Uint
  // image instead: the colour alone as RGB9E5, for the composite's local-mean correction to read
  graph::ResourceId color_out = 0;
  std::optional<graph::ResourceId> color_history;  // also written (persistent R32Uint, RGB9E5 words) at the history tap
  std::string prefix;                              // of the pass name: "specular." for the second signal
  // Packed surface texels (8 bytes a pixel: depth, its gradient, normal): written by the first packed
  // iteration, read by every packed-in one instead of depth_normal.
  std::optional<graph::ResourceId> surface;
  // Read by the first packed iteration's variance estimate: the moments, R32Uint words (temporal.hpp),
  // and the albedo the signal is re-modulated by (the spatial estimate compares radiance).
  std::optional<VarianceEstimateInputs> estimate;
  // A one-signal chain's last packed-in iteration may do the composite pass's work itself
  // (specular must be absent): it writes hdr and display instead of color_out, and its pass is
  // named "<prefix>atrous.<iteration + 1>+composite". The illumination it composites is its own
  // result, so `composite->illumination` is not read.
  std::optional<CompositeResources> composite;
  // The local-mean correction's block sums of this iteration's result (local_mean.hpp), written here
  // so that no pass reads the result again to sum it: by the first packed iteration with the history
  // tap, with the temporal result's terms (color_in's), or by a packed-in last iteration, with the
  // temporal terms taken from `temporal_sums` (the history's block sums of the same blocks).
  struct LocalMeanSums {
    graph::ResourceId block_sums = 0;  // written: RGBA32F, one texel a block
    std::optional<graph::ResourceId> temporal_sums;
    int block = 1;  // pixels a block's side: 1, 2, 4 or 8
  };
  std::optional<LocalMeanSums> local_mean_sums;
  // A packed middle iteration after the history tap may write the colour history itself
  // (color_history): the previous iteration's result, its centre texel, corrected toward the temporal
  // result's local mean with the history's box means (local_mean.hpp), so that the tapped result is
  // not written to an image and read back.
  struct HistoryCorrection {
    graph::ResourceId box_means = 0;
    int block = 1, radius = 0;  // local_mean.hpp's LocalMeanBlocks
  };
  std::optional<HistoryCorrection> corrects_history;
  // Appended to the pass name: a twin that writes the same iteration's result in another form.
  std::string name_suffix;
};
// Adds "<prefix>atrous.<iteration + 1>" with step 2^iteration and the settings' kernel and sigmas.
// The dispatch covers depth_normal's size. Throws std::invalid_argument for a buffer out from an
// image in at an iteration other than 0, for colour images of another size or buffers smaller
// than 8 bytes a pixel, for a packed iteration without `surface`, for the first packed iteration
// without moments (or moments given to another), for `composite` on another iteration or with a
// specular signal, for local_mean_sums anywhere but the first packed iteration (without
// temporal_sums) or a packed-in last one without the history tap (with them), for an R32Uint
// color_out anywhere but such a last one, for corrects_history anywhere but a packed middle
// iteration with color_history, and for a color_history (or a first packed iteration's color_in)
// that is not R32Uint.
graph::PassBuilder add_atrous(graph::RenderGraph& graph, PipelineCache& pipelines, const AtrousResources& r,
                              int iteration, const DenoiseSettings& settings);

}  // namespace asvgf::passes
