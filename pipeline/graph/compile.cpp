// Compiling a render graph: culling, ordering, placement (aliasing, ping-pong) and barriers.
#include <algorithm>
#include <map>
#include <set>

#include "graph/graph_runtime.hpp"

namespace asvgf::graph {
namespace {

std::string quoted(const std::string& s) { return "'" + s + "'"; }

std::uint64_t bytes(const ResourceDecl& d) {
  return d.kind == hal::ResourceKind::Buffer ? d.size
                                             : std::uint64_t(d.width) * d.height * hal::format_size(d.format);
}

// Accesses of one pass, one per (resource, history) with read/write folded together.
struct Merged {
  ResourceId resource;
  bool history;
  bool read, write;
  hal::State needs;
};
std::vector<Merged> merge(const std::vector<PassAccess>& accesses) {
  std::vector<Merged> out;
  for (const PassAccess& a : accesses) {
    auto it = std::find_if(out.begin(), out.end(),
                           [&](const Merged& m) { return m.resource == a.resource && m.history == a.history; });
    if (it == out.end()) {
      out.push_back({a.resource, a.history, reads(a.use), writes(a.use), required_state(a.use)});
      continue;
    }
    it->read = it->read || reads(a.use);
    if (writes(a.use)) it->write = true, it->needs = required_state(a.use);
  }
  return out;
}

}  // namespace

bool GraphRuntime::same_shape(const Slot& slot, const ResourceDecl& d) const {
  return slot.kind == d.kind && slot.width == d.width && slot.height == d.height && slot.format == d.format &&
         slot.size == d.size;
}

CompiledFrame GraphRuntime::compile(const RenderGraph& graph) {
  const auto& passes = graph.passes();
  const auto& res = graph.resources();
  CompiledFrame out;
  out.graph = &graph;
  out.frame = frame_;
  out.placement.resize(res.size());
  out.lifetime.assign(res.size(), {-1, -1});

  for (const auto& p : passes)
    for (const auto& a : p.accesses)
      if (a.resource >= res.size())
        throw GraphError("pass " + quoted(p.name) + " uses resource id " + std::to_string(a.resource) +
                         ", which the graph does not declare");

  // Writers of each resource this frame (skipped passes' writers apart).
  const std::size_t n = passes.size();
  std::vector<bool> skipped(n);
  for (std::size_t i = 0; i < n; ++i) skipped[i] = !passes[i].skip_reason.empty();
  std::vector<std::vector<std::size_t>> writers(res.size()), skipped_writers(res.size());
  for (std::size_t i = 0; i < n; ++i)
    for (const auto& a : passes[i].accesses)
      if (writes(a.use) && !a.history) (skipped[i] ? skipped_writers : writers)[a.resource].push_back(i);

  std::vector<std::vector<PassAccess>> accesses(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (skipped[i]) continue;
    for (const PassAccess& a : passes[i].accesses) {
      const ResourceDecl& r = res[a.resource];
      const bool needs_writer = reads(a.use) && !a.history && r.lifetime != Lifetime::Imported;
      bool has_writer = false;
      for (std::size_t w : writers[a.resource]) has_writer = has_writer || w != i;
      if (needs_writer && !has_writer) {
        if (!skipped_writers[a.resource].empty()) {
          const auto& w = passes[skipped_writers[a.resource].front()];
          throw GraphError("pass " + quoted(passes[i].name) + " reads " + quoted(r.name) + ", whose writer " +
                           quoted(w.name) + " is left out (" + w.skip_reason + ")");
        }
        throw GraphError("pass " + quoted(passes[i].name) + " reads " + quoted(r.name) +
                         ", which no pass writes and which is neither a history nor imported");
      }
      accesses[i].push_back(a);
    }
  }

  // Culling: keep what contributes to an output, directly or through a history read next frame.
  std::vector<bool> live(n), needed(res.size()), history_needed(res.size());
  for (ResourceId o : graph.outputs()) needed[o] = true;
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t i = n; i-- > 0;) {
      if (skipped[i] || live[i]) continue;
      bool contributes = false;
      for (const auto& a : accesses[i])
        if (writes(a.use) && !a.history && (needed[a.resource] || history_needed[a.resource])) contributes = true;
      if (!contributes) continue;
      live[i] = changed = true;
      for (const auto& a : accesses[i]) {
        if (a.history) history_needed[a.resource] = true;
        else if (reads(a.use)) needed[a.resource] = true;
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (skipped[i]) {
      out.culled.push_back({passes[i].name, passes[i].skip_reason});
    } else if (!live[i]) {
      std::string written;
      for (const auto& a : accesses[i])
        if (writes(a.use)) written += (written.empty() ? "" : ", ") + quoted(res[a.resource].name);
      out.culled.push_back({passes[i].name, "nothing that contributes to the frame's outputs reads what it writes (" +
                                                (written.empty() ? std::string("nothing") : written) + ")"});
    }
  }

  // Ordering: a reader comes after every other writer of what it reads (Kahn, ties by declaration).
  // Passes that read-modify-write one resource (counters both accumulate into) would each come after
  // the other: among themselves they keep their declaration order.
  std::vector<std::set<std::size_t>> after(n);  // after[w] = passes that must follow w
  std::vector<int> indegree(n);
  for (std::size_t p = 0; p < n; ++p) {
    if (!live[p]) continue;
    for (const auto& a : accesses[p]) {
      if (!reads(a.use) || a.history) continue;
      for (std::size_t w : writers[a.resource])
        if (w != p && live[w] && !(writes(a.use) && w > p) && after[w].insert(p).second) ++indegree[p];
    }
  }
  std::vector<std::size_t> order;
  std::vector<bool> placed(n);
  for (;;) {
    std::size_t next = n;
    for (std::size_t i = 0; i < n && next == n; ++i)
      if (live[i] && !placed[i] && indegree[i] == 0) next = i;
    if (next == n) break;
    placed[next] = true;
    order.push_back(next);
    for (std::size_t s : after[next]) --indegree[s];
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!live[i] || placed[i]) continue;
    std::string through;
    for (const auto& a : accesses[i])
      if (reads(a.use) && !a.history)
        for (std::size_t w : writers[a.resource])
          if (w != i && live[w] && !placed[w] && through.empty())
            through = quoted(passes[w].name) + " through " + quoted(res[a.resource].name);
    throw GraphError("cycle: pass " + quoted(passes[i].name) + " and " + through + " depend on each other");
  }
  // Two writers of one resource must be ordered by a dependency, not by accident of declaration.
  std::vector<int> position(n, -1);
  for (std::size_t k = 0; k < order.size(); ++k) position[order[k]] = static_cast<int>(k);
  auto reaches = [&](std::size_t from, std::size_t to) {
    std::vector<bool> seen(n);
    std::vector<std::size_t> stack{from};
    while (!stack.empty()) {
      std::size_t v = stack.back();
      stack.pop_back();
      if (v == to) return true;
      for (std::size_t s : after[v])
        if (!seen[s]) seen[s] = true, stack.push_back(s);
    }
    return false;
  };
  for (std::size_t r = 0; r < res.size(); ++r) {
    std::vector<std::size_t> w;
    for (std::size_t p : writers[r])
      if (live[p]) w.push_back(p);
    for (std::size_t a = 0; a < w.size(); ++a)
      for (std::size_t b = a + 1; b < w.size(); ++b)
        if (!reaches(w[a], w[b]) && !reaches(w[b], w[a]))
          throw GraphError("passes " + quoted(passes[w[a]].name) + " and " + quoted(passes[w[b]].name) +
                           " both write " + quoted(res[r].name) + " with no order between them");
  }

  // Placement: lifetimes, transient aliasing (greedy over the pool), persistent ping-pong.
  for (std::size_t k = 0; k < order.size(); ++k)
    for (const auto& a : accesses[order[k]]) {
      auto& life = out.lifetime[a.resource];
      if (life.first < 0) life.first = static_cast<int>(k);
      life.second = static_cast<int>(k);
    }
  std::vector<ResourceId> transients;
  for (ResourceId r = 0; r < res.size(); ++r) {
    if (out.lifetime[r].first < 0) continue;
    switch (res[r].lifetime) {
      case Lifetime::Transient: transients.push_back(r); break;
      case Lifetime::Persistent:
        out.placement[r] = {Placement::Where::Persistent, static_cast<std::uint32_t>(frame_ % 2)};
        out.memory.persistent += 2 * bytes(res[r]);
        break;
      case Lifetime::Imported: out.placement[r] = {Placement::Where::Imported, 0}; break;
    }
  }
  std::stable_sort(transients.begin(), transients.end(),
                   [&](ResourceId a, ResourceId b) { return out.lifetime[a].first < out.lifetime[b].first; });
  std::vector<Slot> pool = slots_;
  std::vector<int> busy_until(pool.size(), -1);
  for (ResourceId r : transients) {
    out.memory.transient_without_aliasing += bytes(res[r]);
    std::size_t slot = pool.size();
    for (std::size_t s = 0; s < pool.size() && slot == pool.size(); ++s)
      if (same_shape(pool[s], res[r]) && busy_until[s] < out.lifetime[r].first) slot = s;
    if (slot == pool.size()) {
      pool.push_back({res[r].kind, res[r].width, res[r].height, res[r].format, res[r].size, {}});
      busy_until.push_back(-1);
      out.new_slots.push_back(static_cast<std::uint32_t>(slot));
    }
    if (busy_until[slot] < 0) out.memory.transient_with_aliasing += bytes(res[r]);
    busy_until[slot] = out.lifetime[r].second;
    out.placement[r] = {Placement::Where::Transient, static_cast<std::uint32_t>(slot)};
  }

  // Barriers: per physical resource, transition when the state differs, synchronise on hazards.
  struct Track {
    hal::State state = hal::State::Undefined;
    bool written = false, pending_write = false, pending_read = false, fresh = false;
    ResourceId owner = 0;  // transients: the resource that last used the slot
    bool owned = false;
  };
  std::map<std::string, Track> tracks;
  auto key = [&](ResourceId r, bool history) -> std::string {
    const Placement& p = out.placement[r];
    switch (p.where) {
      case Placement::Where::Transient: return "t" + std::to_string(p.slot);  // shared by its owners
      case Placement::Where::Persistent: return "p" + res[r].name + "#" + std::to_string(history ? 1 - p.slot : p.slot);
      default: return "i" + std::to_string(r);
    }
  };
  auto track_of = [&](ResourceId r, bool history) -> Track& {
    const std::string k = key(r, history);
    auto it = tracks.find(k);
    if (it != tracks.end()) return it->second;
    Track t;
    const Placement& p = out.placement[r];
    if (p.where == Placement::Where::Imported) {
      t.state = res[r].imported_state;
      t.written = true;
    } else if (p.where == Placement::Where::Transient) {
      // Whatever the slot's last owner (last frame) left: wait for it before taking the slot over.
      if (p.slot < slots_.size()) {
        t.state = slots_[p.slot].state;
        t.pending_write = slots_[p.slot].pending;
      }
    } else if (p.where == Placement::Where::Persistent) {
      auto pit = persistent_.find(res[r].name);
      const std::uint32_t v = history ? 1 - p.slot : p.slot;
      if (pit != persistent_.end() && same_shape(Slot{res[r].kind, res[r].width, res[r].height, res[r].format,
                                                      res[r].size, {}},
                                                 pit->second.decl)) {
        t.state = pit->second.state[v];
        t.written = pit->second.written[v];
        t.pending_write = pit->second.pending_write[v];
        t.pending_read = pit->second.pending_read[v];
      }
    }
    return tracks.emplace(k, t).first->second;
  };
  for (std::size_t idx : order) {
    CompiledPass cp;
    cp.pass = idx;
    for (const Merged& m : merge(accesses[idx])) {
      Track& t = track_of(m.resource, m.history);
      if (out.placement[m.resource].where == Placement::Where::Transient && (!t.owned || t.owner != m.resource)) {
        // First use of this resource in a shared slot: whatever the slot holds belongs to another.
        t.fresh = true;
        t.owner = m.resource;
        t.owned = true;
      }
      if (m.history && !t.written) {
        cp.history_clears.push_back(m.resource);
        t = Track{hal::State::CopyDst, true, true, false, false, 0, false};
      }
      const bool hazard = t.pending_write || (m.write && t.pending_read);
      if (t.fresh || t.state != m.needs || hazard) {
        // Taking over a slot: from Undefined when nothing used it, else wait for the old owner and
        // discard its contents.
        cp.barriers.push_back({m.resource, m.history, t.state, m.needs, t.fresh && t.state != hal::State::Undefined});
        t.state = m.needs;
        t.pending_write = t.pending_read = t.fresh = false;
      }
      if (m.write) t.pending_write = true, t.pending_read = false, t.written = true;
      else t.pending_read = true;
    }
    out.passes.push_back(std::move(cp));
  }
  for (std::size_t o = 0; o < graph.outputs().size(); ++o) {
    const auto final_state = graph.output_states()[o];
    const ResourceId r = graph.outputs()[o];
    if (!final_state || out.placement[r].where == Placement::Where::Unused) continue;
    Track& t = track_of(r, false);
    if (t.state != *final_state || t.pending_write || t.pending_read) {
      out.final_barriers.push_back({r, false, t.state, *final_state});
      t.state = *final_state;
      t.pending_write = t.pending_read = false;
    }
  }
  for (const auto& [k, t] : tracks)
    if (k[0] == 't')
      out.slot_end.push_back({static_cast<std::uint32_t>(std::stoul(k.substr(1))), t.state,
                              t.pending_write || t.pending_read});
  for (ResourceId r = 0; r < res.size(); ++r) {
    if (out.placement[r].where != Placement::Where::Persistent) continue;
    for (bool history : {false, true}) {
      auto it = tracks.find(key(r, history));
      if (it == tracks.end()) continue;
      const std::uint32_t v = history ? 1 - out.placement[r].slot : out.placement[r].slot;
      const Track& t = it->second;
      out.persistent_end.push_back({res[r].name, v, t.state, t.written, t.pending_write, t.pending_read});
    }
  }
  return out;
}

}  // namespace asvgf::graph
