#include "passes/composite.hpp"

#include <cstddef>

#include "graph/graph_runtime.hpp"
#include "passes/compute_pass.hpp"
#include "shaders/composite.hpp"

namespace asvgf::passes {
namespace {

struct Uniforms {
  std::uint32_t width, height;
  float exposure;
  std::uint32_t tonemap;
};
static_assert(sizeof(Uniforms) == 16);

}  // namespace

CompositePass::CompositePass(hal::Device& device) : device_(device) {
  const hal::ShaderInfo& shader = asvgf::shaders::composite;
  check_uniform_layout(shader, sizeof(Uniforms),
                       {{"width", offsetof(Uniforms, width)},
                        {"height", offsetof(Uniforms, height)},
                        {"exposure", offsetof(Uniforms, exposure)},
                        {"tonemap", offsetof(Uniforms, tonemap)}});
  pipeline_ = device_.create_pipeline({"composite", &shader, {}});
}

CompositePass::~CompositePass() { device_.destroy(pipeline_); }

void CompositePass::add(graph::RenderGraph& graph, const Resources& r, const DenoiseSettings& s) const {
  const auto& decl = graph.resource(r.hdr);
  const Uniforms u{decl.width, decl.height, s.exposure, static_cast<std::uint32_t>(s.tonemap)};
  const hal::ShaderInfo& shader = asvgf::shaders::composite;
  add_compute_pass(graph, "composite", shader, pipeline_,
                   {{"illumination", r.illumination},
                    {"albedo", r.albedo},
                    {"hdr", r.hdr},
                    {"display", r.display},
                    {"counters", r.counters}},
                   to_bytes(u), {u.width, u.height, 1});
}

}  // namespace asvgf::passes
