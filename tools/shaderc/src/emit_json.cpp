#include <nlohmann/json.hpp>

#include "emit.hpp"
#include "portability.hpp"

namespace shaderc {

std::string json_text(const Options& o, const Reflection& r, const Targets& targets) {
  using nlohmann::json;
  json bindings = json::array();
  for (const auto& b : r.bindings) {
    json j = {{"set", b.set},
              {"binding", b.binding},
              {"kind", kind_name(b.kind)},
              {"access", access_name(b.access)},
              {"name", b.name},
              {"gl_binding", b.gl_binding}};
    if (!b.format.empty()) j["format"] = b.format;
    bindings.push_back(std::move(j));
  }
  json members = json::array();
  for (const auto& m : r.uniform_members) members.push_back({{"name", m.name}, {"offset", m.offset}, {"size", m.size}});

  json doc = {
      {"name", o.full_name()},
      {"shader", o.shader},
      {"variant", o.variant},
      {"source", o.source.filename().string()},
      {"workgroup_size", r.workgroup_size},
      {"bindings", bindings},
      {"uniform_block_size", r.uniform_block_size},
      {"uniform_members", members},
      {"uses_ray_query", r.uses_ray_query},
      {"es31_minimum", r.uses_ray_query ? "no ESSL (ray queries)" : es31_minimum_fit(r)},
      {"targets", targets.emitted},
      {"skipped_targets", targets.skipped},
  };
  return doc.dump(2) + "\n";
}

}  // namespace shaderc
