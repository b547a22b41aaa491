// Printing a compiled frame: text for people, Graphviz for pictures.
#include <sstream>

#include "asvgf/compiled_frame.hpp"

namespace asvgf::graph {
namespace {

std::string use_name(const PassAccess& a) {
  if (a.history) return "history";
  switch (a.use) {
    case Use::ShaderRead:
      return "read";
    case Use::ShaderWrite:
      return "write";
    case Use::ShaderReadWrite:
      return "read-write";
    case Use::CopySrc:
      return "copy-src";
    case Use::CopyDst:
      return "copy-dst";
    case Use::AccelRead:
      return "accel";
  }
  return "?";
}

std::string mib(std::uint64_t bytes) {
  std::ostringstream s;
  s.precision(2);
  s << std::fixed << double(bytes) / (1024.0 * 1024.0) << " MiB";
  return s.str();
}

std::string place(const CompiledFrame& f, ResourceId r) {
  const Placement& p = f.placement[r];
  switch (p.where) {
    case Placement::Where::Transient:
      return "transient slot " + std::to_string(p.slot);
    case Placement::Where::Persistent:
      return "persistent, writes version " + std::to_string(p.slot);
    case Placement::Where::Imported:
      return "imported";
    case Placement::Where::Unused:
      return "unused";
  }
  return "?";
}

}  // namespace

std::string CompiledFrame::text() const {
  std::ostringstream s;
  const auto& res = graph->resources();
  s << "frame " << frame << ": " << passes.size() << " passes, " << culled.size() << " left out\n";
  for (std::size_t k = 0; k < passes.size(); ++k) {
    const PassDecl& p = graph->passes()[passes[k].pass];
    s << "  " << k + 1 << ". " << p.name << "\n";
    for (ResourceId r : passes[k].history_clears) s << "       clear history " << res[r].name << " (never written)\n";
    for (const auto& b : passes[k].barriers)
      s << "       barrier " << res[b.resource].name << (b.history ? " (history)" : "") << ": "
        << hal::to_string(b.before) << " -> " << hal::to_string(b.after) << (b.discard ? " (discard)" : "") << "\n";
    for (const auto& a : p.accesses) s << "       " << use_name(a) << " " << res[a.resource].name << "\n";
  }
  for (const auto& b : final_barriers)
    s << "  end: barrier " << res[b.resource].name << ": " << hal::to_string(b.before) << " -> "
      << hal::to_string(b.after) << "\n";
  if (!culled.empty()) {
    s << "left out:\n";
    for (const auto& c : culled) s << "  " << c.name << ": " << c.reason << "\n";
  }
  s << "resources:\n";
  for (ResourceId r = 0; r < res.size(); ++r) {
    if (placement[r].where == Placement::Where::Unused) continue;
    s << "  " << res[r].name << ": " << place(*this, r);
    if (lifetime[r].first >= 0) s << ", passes " << lifetime[r].first + 1 << "-" << lifetime[r].second + 1;
    s << "\n";
  }
  s << "memory: transient " << mib(memory.transient_with_aliasing) << " with aliasing, "
    << mib(memory.transient_without_aliasing) << " without; persistent (2 versions) " << mib(memory.persistent) << "\n";
  return s.str();
}

std::string CompiledFrame::dot() const {
  std::ostringstream s;
  const auto& res = graph->resources();
  s << "digraph frame_" << frame << " {\n  rankdir=LR;\n  node [fontname=\"Helvetica\"];\n";
  for (ResourceId r = 0; r < res.size(); ++r)
    if (placement[r].where != Placement::Where::Unused)
      s << "  r" << r << " [shape=ellipse, label=\"" << res[r].name << "\\n" << place(*this, r) << "\"];\n";
  for (std::size_t k = 0; k < passes.size(); ++k) {
    const PassDecl& p = graph->passes()[passes[k].pass];
    std::string barriers;
    for (const auto& b : passes[k].barriers)
      barriers += "\\n" + res[b.resource].name + ": " + std::string(hal::to_string(b.before)) + "->" +
                  std::string(hal::to_string(b.after));
    s << "  p" << passes[k].pass << " [shape=box, style=filled, fillcolor=\"#d8e8ff\", label=\"" << k + 1 << ". "
      << p.name << barriers << "\"];\n";
    for (const auto& a : p.accesses) {
      if (placement[a.resource].where == Placement::Where::Unused) continue;
      if (writes(a.use)) s << "  p" << passes[k].pass << " -> r" << a.resource << ";\n";
      if (reads(a.use))
        s << "  r" << a.resource << " -> p" << passes[k].pass << (a.history ? " [style=dashed, label=\"history\"]" : "")
          << ";\n";
    }
  }
  for (const auto& c : culled)
    s << "  \"" << c.name << "\" [shape=box, style=dashed, fontcolor=gray, label=\"" << c.name
      << "\\n(left out: " << c.reason << ")\"];\n";
  s << "}\n";
  return s.str();
}

}  // namespace asvgf::graph
