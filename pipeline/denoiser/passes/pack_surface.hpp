// denoiser/passes/pack_surface.hpp: the `pack_surface` pass (shaders/denoise/pack_surface.comp): a renderer's
// linear depth and world-space normal as the denoiser's depth_normal texel. The public API's first
// pass; the frame's own G-buffer writes depth_normal directly.
#pragma once

#include "asvgf/compute_pass.hpp"
#include "asvgf/render_graph.hpp"

namespace asvgf::passes {

struct PackSurfaceResources {
  graph::ResourceId depth = 0;         // read: x linear view depth, y its gradient when `depth_gradient_given`
  graph::ResourceId normal = 0;        // read: xyz world-space normal (any length)
  graph::ResourceId depth_normal = 0;  // written: RGBA16UI (shaders/common/depth_normal.glsl), 0 on background
};
// Adds "pack_surface".
graph::PassBuilder add_pack_surface(graph::RenderGraph& graph, PipelineCache& pipelines, const PackSurfaceResources& r,
                                    bool depth_gradient_given);

}  // namespace asvgf::passes
