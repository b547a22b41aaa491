// denoiser/passes/local_mean.hpp: the local-mean correction (shaders/denoise/local_mean.comp,
// DenoiseSettings::local_mean): the filtered colour scaled toward the temporal result's local mean
// of luminance over about k x k pixels, where that mean is known better than its difference from the
// filtered one's.
#pragma once

#include <optional>
#include <string>

#include "asvgf/compute_pass.hpp"
#include "asvgf/denoise_settings.hpp"
#include "asvgf/render_graph.hpp"

namespace asvgf::passes {

struct LocalMeanResources {
  graph::ResourceId temporal = 0;  // read: the temporal pass's result (R32Uint, RGB9E5 words)
  // Read: the last a-trous iteration's output (RGBA16F image), or the tapped colour history (R32Uint,
  // RGB9E5 words, as the history is kept).
  graph::ResourceId filtered = 0;
  graph::ResourceId corrected = 0;  // written, in filtered's format: the filtered colour scaled (alpha kept)
  std::string name = "local_mean";  // of the passes: the displayed colour's, or the tapped history's
  bool gated = true;                // false: the plain ratio (local_mean.comp)
  // Read where given, instead of the temporal result: the block sums of another correction of the
  // same k over the same temporal result (its x, z and w are this one's; the history's and the
  // displayed colour's corrections share them).
  std::optional<graph::ResourceId> temporal_sums;
  // Given: the block sums made already (by an a-trous iteration, atrous.hpp's LocalMeanSums, in an
  // image of add_local_mean_sums_image's): no blocks pass.
  std::optional<graph::ResourceId> block_sums;
  // false: no "<name>" pass (an a-trous iteration applies the correction: atrous.hpp's
  // HistoryCorrection); `filtered` and `corrected` are then not read or written.
  bool apply_pass = true;
};
// How a window of k pixels is built from blocks (local_mean.comp): blocks of `block` pixels a side
// (1 up to k 15, so that small windows are exact; then 2, 4, 8 with k), `radius` blocks either side of
// a block, so that the window is (2 radius + 1) block pixels wide (k 65: 72; k 33: 36).
struct LocalMeanBlocks {
  int block = 1;
  int radius = 0;
};
LocalMeanBlocks local_mean_blocks(int k);
// The largest radius local_mean.comp's box pass holds in shared memory (its kMaxRadius): k 255.
inline constexpr int kLocalMeanMaxRadius = 15;

// The images a correction declares, one texel a block, RGBA32F (OpenGL ES has no RG32F storage
// images): the block sums (x: temporal, y: filtered, z: temporal squared, w: pixels) and the
// blocks' windows' means (the composite's LOCAL_MEAN variant reads them to correct by itself).
struct LocalMeanImages {
  graph::ResourceId block_sums = 0;
  graph::ResourceId box_means = 0;
  LocalMeanBlocks blocks;  // the window they were made for, which whoever applies them needs
};
// Declares "<name>_block_sums", the block sums' RGBA32F image for a width x height image and window k.
graph::ResourceId add_local_mean_sums_image(graph::RenderGraph& graph, const std::string& name, std::uint32_t width,
                                            std::uint32_t height, int k);

// Adds "<name>.blocks" (unless r.block_sums), "<name>.box" and "<name>" (unless !r.apply_pass), for
// local_mean_window(settings, ...) > 0. "<name>" writes `corrected` and, like every pass, runs only
// where something reads it. Throws std::invalid_argument for formats other than those above, and for
// temporal_sums with an R32Uint `filtered`.
LocalMeanImages add_local_mean(graph::RenderGraph& graph, PipelineCache& pipelines, const LocalMeanResources& r,
                               const DenoiseSettings& settings);

}  // namespace asvgf::passes
