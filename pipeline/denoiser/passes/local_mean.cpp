#include "denoiser/passes/local_mean.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "shaders/local_mean.apply.hpp"
#include "shaders/local_mean.apply_rgb9e5.hpp"
#include "shaders/local_mean.blocks.hpp"
#include "shaders/local_mean.blocks_filtered.hpp"
#include "shaders/local_mean.blocks_rgb9e5.hpp"
#include "shaders/local_mean.box.hpp"

namespace asvgf::passes {
namespace {

// The shaders' uniform block, as the shader tool generated it (the same for every variant).
using Uniforms = asvgf::shaders::local_mean_apply_uniforms::Params;

// The blocks' grid of a width x height image: partial blocks at the right and bottom edges
// (common/local_mean.glsl's local_mean_blocks).
std::pair<std::uint32_t, std::uint32_t> blocks_grid(std::uint32_t width, std::uint32_t height, int k) {
  const std::uint32_t block = static_cast<std::uint32_t>(local_mean_blocks(k).block);
  return {(width + block - 1) / block, (height + block - 1) / block};
}

}  // namespace

LocalMeanBlocks local_mean_blocks(int k) {
  int block = 1;
  while (block < 8 && k >= 16 * block) block *= 2;  // k 3..15: 1 (exact), 16..31: 2, 32..63: 4, 64..255: 8
  const int radius = std::max(0, static_cast<int>(std::lround((double(k) / block - 1.0) / 2.0)));
  return {block, radius};
}

graph::ResourceId add_local_mean_sums_image(graph::RenderGraph& graph, const std::string& name, std::uint32_t width,
                                            std::uint32_t height, int k) {
  const auto [bw, bh] = blocks_grid(width, height, k);
  return graph.add_image(name + "_block_sums", bw, bh, hal::Format::RGBA32F);
}

LocalMeanImages add_local_mean(graph::RenderGraph& graph, PipelineCache& pipelines, const LocalMeanResources& r,
                               const DenoiseSettings& s) {
  // Copies, not references: declaring an image may move the graph's resources.
  const std::uint32_t width = graph.resource(r.temporal).width;  // the size of every image it corrects
  const std::uint32_t height = graph.resource(r.temporal).height;
  const int k = local_mean_window(s, width, height);
  const LocalMeanBlocks b = local_mean_blocks(k);
  if (b.radius > kLocalMeanMaxRadius)
    throw std::invalid_argument("add_local_mean: window " + std::to_string(k) + " needs " + std::to_string(b.radius) +
                                " blocks a side, more than the box pass holds (" + std::to_string(kLocalMeanMaxRadius) +
                                ")");
  // The tapped history's correction reads and writes RGB9E5 words, as the colour history is kept;
  // the displayed colour's, RGBA16F.
  const bool rgb9e5 = graph.resource(r.filtered).format == hal::Format::R32Uint;
  if (graph.resource(r.temporal).format != hal::Format::R32Uint ||
      graph.resource(r.corrected).format != graph.resource(r.filtered).format ||
      (!rgb9e5 && graph.resource(r.filtered).format != hal::Format::RGBA16F))
    throw std::invalid_argument("add_local_mean: the temporal result '" + graph.resource(r.temporal).name +
                                "' is R32Uint (RGB9E5 words), and '" + graph.resource(r.filtered).name + "' and '" +
                                graph.resource(r.corrected).name + "' are both RGBA16F or both R32Uint");
  const Uniforms u{width, height, b.radius, r.gated ? 1u : 0u, b.block};
  const graph::ResourceId sums =
      r.block_sums ? *r.block_sums : add_local_mean_sums_image(graph, r.name, width, height, k);
  const auto [bw, bh] = blocks_grid(width, height, k);
  if (graph.resource(sums).width != bw || graph.resource(sums).height != bh)
    throw std::invalid_argument("add_local_mean: '" + graph.resource(sums).name + "' is not the blocks' grid of k " +
                                std::to_string(k));
  const graph::ResourceId means = graph.add_image(r.name + "_box_means", bw, bh, hal::Format::RGBA32F);
  if (!r.block_sums) {
    if (r.temporal_sums && rgb9e5)
      throw std::invalid_argument("add_local_mean: the temporal terms' sums are the displayed colour's (RGBA16F)");
    const hal::ShaderInfo& blocks_shader = r.temporal_sums ? asvgf::shaders::local_mean_blocks_filtered
                                           : rgb9e5        ? asvgf::shaders::local_mean_blocks_rgb9e5
                                                           : asvgf::shaders::local_mean_blocks;
    add_compute_pass(graph, r.name + ".blocks", blocks_shader, pipelines.get<Uniforms>(blocks_shader),
                     {r.temporal_sums ? Binding{"temporal_sums", *r.temporal_sums} : Binding{"temporal", r.temporal},
                      {"filtered", r.filtered},
                      {"block_sums", sums}},
                     to_bytes(u), {u.width, u.height, 1});
  }
  const hal::ShaderInfo& box_shader = asvgf::shaders::local_mean_box;
  add_compute_pass(graph, r.name + ".box", box_shader, pipelines.get<Uniforms>(box_shader),
                   {{"block_sums", sums}, {"box_means", means}}, to_bytes(u), {bw, bh, 1});
  if (!r.apply_pass) return {sums, means, b};
  const hal::ShaderInfo& apply_shader =
      rgb9e5 ? asvgf::shaders::local_mean_apply_rgb9e5 : asvgf::shaders::local_mean_apply;
  add_compute_pass(graph, r.name, apply_shader, pipelines.get<Uniforms>(apply_shader),
                   {{"box_means", means}, {"filtered", r.filtered}, {"corrected", r.corrected}}, to_bytes(u),
                   {u.width, u.height, 1});
  return {sums, means, b};
}

}  // namespace asvgf::passes
