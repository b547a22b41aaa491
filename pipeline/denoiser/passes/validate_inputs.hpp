// denoiser/passes/validate_inputs.hpp: the `validate_inputs` pass (shaders/denoise/validate_inputs.comp):
// counts a frame's input problems into a buffer of kInputCounts uints (cleared first by the pass
// "validate_clear"), for asvgf::Denoiser's validate option.
#pragma once

#include <cstdint>

#include "asvgf/compute_pass.hpp"
#include "asvgf/render_graph.hpp"

namespace asvgf::passes {

// The counters, in the shader's order.
enum InputCount : std::uint32_t {
  kPixels,
  kIlluminationNotFinite,
  kIlluminationNegative,
  kAlbedoInvalid,
  kSurfacePixels,
  kNormalNotUnit,
  kNormalNotFinite,
  kDepthNotFinite,
  kDepthNegative,
  kMotionNotFinite,
  kMovingPixels,
  kMovingConsistent,
  kMovingConsistentNegated,
  kIlluminationAboveFp16,
  kInputCounts = 16
};

struct ValidateInputsResources {
  graph::ResourceId illumination = 0, albedo = 0, normal = 0, depth = 0, motion = 0;  // the caller's
  graph::ResourceId depth_normal = 0;  // persistent: its history (last frame's depth) is read
  graph::ResourceId counts = 0;        // buffer of kInputCounts uints, cleared and counted into
};
// Adds "validate_clear" and "validate_inputs".
void add_validate_inputs(graph::RenderGraph& graph, PipelineCache& pipelines, const ValidateInputsResources& r);

}  // namespace asvgf::passes
