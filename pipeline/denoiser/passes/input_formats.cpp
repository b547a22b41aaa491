#include "denoiser/passes/input_formats.hpp"

#include <stdexcept>

namespace asvgf::passes {
namespace {

// true for an R32Uint image, false for a float one; else throws, naming the image `what` holds.
bool words_or_floats(const graph::RenderGraph& graph, graph::ResourceId id, const std::string& pass,
                     const std::string& what, const std::string& words) {
  const auto& decl = graph.resource(id);
  const bool image = decl.kind == hal::ResourceKind::Image;
  if (image && decl.format == hal::Format::R32Uint) return true;
  if (image && decl.format != hal::Format::Undefined && !hal::format_is_uint(decl.format)) return false;
  throw std::invalid_argument(pass + ": the " + what + " '" + decl.name + "' is " +
                              (image ? std::string(hal::format_name(decl.format)) : std::string("a buffer")) +
                              ", not a float format or R32Uint (" + words + ")");
}

}  // namespace

bool albedo_rgb9e5(const graph::RenderGraph& graph, graph::ResourceId albedo, const std::string& pass) {
  return words_or_floats(graph, albedo, pass, "albedo", "RGB9E5 words");
}

bool motion_halves(const graph::RenderGraph& graph, graph::ResourceId motion, const std::string& pass) {
  return words_or_floats(graph, motion, pass, "motion", "x, y as halves");
}

}  // namespace asvgf::passes
