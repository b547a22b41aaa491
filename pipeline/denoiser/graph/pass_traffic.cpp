#include "asvgf/pass_traffic.hpp"

namespace asvgf::graph {
namespace {

// 0 when the declaration does not say (imported without format or size).
std::uint64_t bytes_of(const ResourceDecl& r) {
  if (r.kind == hal::ResourceKind::Buffer) return r.size;
  if (r.kind != hal::ResourceKind::Image) return 0;
  return std::uint64_t{r.width} * r.height * hal::format_size(r.format);
}

}  // namespace

std::vector<PassTraffic> pass_traffic(const CompiledFrame& frame) {
  std::vector<PassTraffic> out;
  const auto& resources = frame.graph->resources();
  for (const CompiledPass& compiled : frame.passes) {
    const PassDecl& pass = frame.graph->passes()[compiled.pass];
    PassTraffic t;
    t.pass = pass.name;
    for (const PassAccess& a : pass.accesses) {
      const std::uint64_t bytes = bytes_of(resources[a.resource]);
      if (bytes == 0 && reads(a.use)) t.uncounted_reads = true;
      if (reads(a.use)) t.read_bytes += bytes;
      if (writes(a.use)) t.written_bytes += bytes;
      t.resources.push_back({resources[a.resource].name, bytes, reads(a.use), writes(a.use), a.history});
    }
    out.push_back(std::move(t));
  }
  return out;
}

}  // namespace asvgf::graph
