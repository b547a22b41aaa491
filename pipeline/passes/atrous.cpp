#include "passes/atrous.hpp"

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "graph/graph_runtime.hpp"
#include "passes/compute_pass.hpp"
#include "shaders/atrous.history.hpp"
#include "shaders/atrous.plain.hpp"

namespace asvgf::passes {
namespace {

struct Uniforms {
  std::uint32_t width, height;
  std::int32_t step;
  std::uint32_t kernel;
  float sigma_z, sigma_n, sigma_l;
};
static_assert(sizeof(Uniforms) == 28);

void check(const hal::ShaderInfo& shader) {
  check_uniform_layout(shader, sizeof(Uniforms),
                       {{"width", offsetof(Uniforms, width)},
                        {"height", offsetof(Uniforms, height)},
                        {"step", offsetof(Uniforms, step)},
                        {"kernel", offsetof(Uniforms, kernel)},
                        {"sigma_z", offsetof(Uniforms, sigma_z)},
                        {"sigma_n", offsetof(Uniforms, sigma_n)},
                        {"sigma_l", offsetof(Uniforms, sigma_l)}});
}

}  // namespace

AtrousPass::AtrousPass(hal::Device& device) : device_(device) {
  check(asvgf::shaders::atrous_plain);
  check(asvgf::shaders::atrous_history);
  plain_ = device_.create_pipeline({"atrous", &asvgf::shaders::atrous_plain, {}});
  history_ = device_.create_pipeline({"atrous (history tap)", &asvgf::shaders::atrous_history, {}});
}

AtrousPass::~AtrousPass() {
  device_.destroy(plain_);
  device_.destroy(history_);
}

void AtrousPass::add(graph::RenderGraph& graph, const Resources& r, int iteration, const DenoiseSettings& s) const {
  const auto& decl = graph.resource(r.color_out);
  const Uniforms u{decl.width,  decl.height, 1 << iteration, static_cast<std::uint32_t>(s.kernel),
                   s.sigma_z, s.sigma_n,   s.sigma_l};
  std::vector<Binding> bindings{{"color_in", r.color_in},
                                {"depth_normal", r.depth_normal},
                                {"color_out", r.color_out}};
  if (r.color_history) bindings.push_back({"color_history", *r.color_history});
  const hal::ShaderInfo& shader = r.color_history ? asvgf::shaders::atrous_history : asvgf::shaders::atrous_plain;
  add_compute_pass(graph, "atrous." + std::to_string(iteration + 1), shader, r.color_history ? history_ : plain_,
                   std::move(bindings), to_bytes(u), {u.width, u.height, 1});
}

graph::ResourceId AtrousPass::add_iterations(graph::RenderGraph& graph, graph::ResourceId input,
                                             graph::ResourceId depth_normal, graph::ResourceId color_history,
                                             const DenoiseSettings& s) const {
  const auto& decl = graph.resource(input);
  const std::uint32_t w = decl.width, h = decl.height;
  graph::ResourceId current = input;
  for (int i = 0; i < s.atrous_iterations; ++i) {
    const graph::ResourceId next = graph.add_image("atrous." + std::to_string(i + 1), w, h, hal::Format::RGBA16F);
    Resources r{current, depth_normal, next, std::nullopt};
    if (i == s.history_tap) r.color_history = color_history;
    add(graph, r, i, s);
    current = next;
  }
  return current;
}

}  // namespace asvgf::passes
