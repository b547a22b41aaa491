// denoiser/passes/input_formats.hpp: the two formats the passes take for the albedo and the motion
// (their shader variants are chosen by the image's format): floats, or 4-byte words.
#pragma once

#include <string>

#include "asvgf/render_graph.hpp"

namespace asvgf::passes {

// Whether the albedo image `albedo` holds RGB9E5 words (R32Uint: shaders/common/albedo.glsl), else
// floats (any float or unorm format); throws std::invalid_argument, naming `pass` and the image, for
// any other format.
bool albedo_rgb9e5(const graph::RenderGraph& graph, graph::ResourceId albedo, const std::string& pass);
// Whether the motion image `motion` holds x and y as two halves a word (R32Uint:
// shaders/common/motion.glsl), else floats; throws as albedo_rgb9e5 does.
bool motion_halves(const graph::RenderGraph& graph, graph::ResourceId motion, const std::string& pass);

}  // namespace asvgf::passes
