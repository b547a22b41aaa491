// renderer/aov_passes.hpp: the frame's denoiser inputs exported in the public API's conventions
// (include/asvgf/denoiser.hpp), for `asvgf render --aovs`: an export pass for depth, normal and
// albedo (shaders/renderer/export_aovs.comp), half-float images widened to RGBA32F
// (shaders/renderer/widen_image.comp) and plain copies for the rest.
#pragma once

#include <string>

#include "asvgf/compute_pass.hpp"
#include "asvgf/render_graph.hpp"

namespace asvgf::passes {

struct ExportAovResources {
  graph::ResourceId depth_normal = 0;                       // read: RGBA16UI (shaders/common/depth_normal.glsl)
  graph::ResourceId albedo = 0;                             // read: R32Uint, RGB9E5 words (the G-buffer's)
  graph::ResourceId depth = 0, normal = 0, albedo_out = 0;  // written: RGBA32F
};
// Adds "export_aovs".
graph::PassBuilder add_export_aovs(graph::RenderGraph& graph, PipelineCache& pipelines, const ExportAovResources& r);

// Adds a pass `name` writing image `src` (any float format, or R32Uint of two halves a word: the
// G-buffer's motion) into the RGBA32F image `dst` of its size.
graph::PassBuilder add_image_widen(graph::RenderGraph& graph, PipelineCache& pipelines, const std::string& name,
                                   graph::ResourceId src, graph::ResourceId dst);

// Adds a pass `name` copying image `src` into `dst` (same size and format).
graph::PassBuilder add_image_copy(graph::RenderGraph& graph, const std::string& name, graph::ResourceId src,
                                  graph::ResourceId dst);

}  // namespace asvgf::passes
