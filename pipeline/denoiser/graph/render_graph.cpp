// Declaring resources and passes.
#include "asvgf/render_graph.hpp"

namespace asvgf::graph {

hal::State required_state(Use use) {
  switch (use) {
    case Use::ShaderRead:
      return hal::State::ShaderRead;
    case Use::ShaderWrite:
    case Use::ShaderReadWrite:
      return hal::State::ShaderWrite;
    case Use::CopySrc:
      return hal::State::CopySrc;
    case Use::CopyDst:
      return hal::State::CopyDst;
    case Use::AccelRead:
      return hal::State::AccelRead;
  }
  return hal::State::Undefined;
}
bool reads(Use use) {
  return use != Use::ShaderWrite && use != Use::CopyDst;
}
bool writes(Use use) {
  return use == Use::ShaderWrite || use == Use::ShaderReadWrite || use == Use::CopyDst;
}

PassDecl& PassBuilder::pass() {
  return graph_.passes()[index_];
}
PassBuilder& PassBuilder::read(ResourceId r, Use use) {
  pass().accesses.push_back({r, use});
  return *this;
}
PassBuilder& PassBuilder::read_history(ResourceId r) {
  if (graph_.resource(r).lifetime != Lifetime::Persistent)
    throw GraphError("pass '" + pass().name + "' reads the history of '" + graph_.resource(r).name +
                     "', which is not persistent");
  pass().accesses.push_back({r, Use::ShaderRead, true});
  return *this;
}
PassBuilder& PassBuilder::write(ResourceId r, Use use) {
  pass().accesses.push_back({r, use});
  return *this;
}
PassBuilder& PassBuilder::read_write(ResourceId r) {
  return write(r, Use::ShaderReadWrite);
}
PassBuilder& PassBuilder::skip_if(bool condition, std::string reason) {
  if (condition) pass().skip_reason = std::move(reason);
  return *this;
}
PassBuilder& PassBuilder::execute(ExecuteFn fn) {
  pass().execute = std::move(fn);
  return *this;
}

ResourceId RenderGraph::add_image(std::string name, std::uint32_t width, std::uint32_t height, hal::Format format,
                                  Lifetime lifetime) {
  ResourceDecl d;
  d.name = std::move(name);
  d.kind = hal::ResourceKind::Image;
  d.lifetime = lifetime;
  d.width = width;
  d.height = height;
  d.format = format;
  resources_.push_back(std::move(d));
  return static_cast<ResourceId>(resources_.size() - 1);
}

ResourceId RenderGraph::add_buffer(std::string name, std::uint64_t size, Lifetime lifetime) {
  ResourceDecl d;
  d.name = std::move(name);
  d.kind = hal::ResourceKind::Buffer;
  d.lifetime = lifetime;
  d.size = size;
  resources_.push_back(std::move(d));
  return static_cast<ResourceId>(resources_.size() - 1);
}

ResourceId RenderGraph::import(std::string name, hal::Resource resource, hal::State state, std::uint32_t width,
                               std::uint32_t height, hal::Format format) {
  ResourceDecl d;
  d.width = width;
  d.height = height;
  d.format = format;
  d.name = std::move(name);
  d.kind = resource.kind;
  d.lifetime = Lifetime::Imported;
  d.imported = resource;
  d.imported_state = state;
  resources_.push_back(std::move(d));
  return static_cast<ResourceId>(resources_.size() - 1);
}

ResourceId RenderGraph::import_buffer(std::string name, hal::BufferHandle buffer, hal::State state,
                                      std::uint64_t size) {
  const ResourceId id = import(std::move(name), buffer, state);
  resources_[id].size = size;
  return id;
}

PassBuilder RenderGraph::add_pass(std::string name) {
  passes_.push_back(PassDecl{std::move(name), {}, {}, {}});
  return PassBuilder(*this, passes_.size() - 1);
}

void RenderGraph::output(ResourceId resource, std::optional<hal::State> final_state) {
  outputs_.push_back(resource);
  output_states_.push_back(final_state);
}

ResourceId RenderGraph::find(const std::string& name) const {
  for (std::size_t i = 0; i < resources_.size(); ++i)
    if (resources_[i].name == name) return static_cast<ResourceId>(i);
  throw GraphError("no resource named '" + name + "'");
}

}  // namespace asvgf::graph
