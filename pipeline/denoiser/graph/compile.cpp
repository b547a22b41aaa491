// Compiling a render graph in five phases: validate, cull, order, place (lifetimes, transient
// aliasing, persistent ping-pong) and barriers; each phase is a function below.
#include <algorithm>
#include <map>
#include <set>

#include "asvgf/graph_runtime.hpp"

namespace asvgf::graph {
namespace {

std::string quoted(const std::string& s) {
  return "'" + s + "'";
}

std::uint64_t bytes(const ResourceDecl& d) {
  return d.kind == hal::ResourceKind::Buffer ? d.size : std::uint64_t(d.width) * d.height * hal::format_size(d.format);
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

// What the phases of compile() hand on to each other. Pass indices are positions in
// RenderGraph::passes(); resource ids are the graph's.
struct Analysis {
  const RenderGraph& graph;
  const std::vector<PassDecl>& passes;
  const std::vector<ResourceDecl>& res;
  std::size_t n = 0;
  std::vector<bool> skipped;                      // left out by the caller, with a reason
  std::vector<std::vector<std::size_t>> writers;  // per resource: passes that write it (not skipped)
  std::vector<std::vector<PassAccess>> accesses;  // per pass: what it uses (empty when skipped)
  std::vector<bool> live;                         // contributes to an output
  std::vector<std::set<std::size_t>> after;       // after[w]: passes that must follow w
  std::vector<std::size_t> order;                 // execution order of the live passes
};

// Phase 1, validate: every access names a declared resource, every read has a writer (or is a
// history or an import); collects writers and the accesses of the passes that are not skipped.
void validate(Analysis& a) {
  const auto& passes = a.passes;
  const auto& res = a.res;
  for (const auto& p : passes)
    for (const auto& acc : p.accesses)
      if (acc.resource >= res.size())
        throw GraphError("pass " + quoted(p.name) + " uses resource id " + std::to_string(acc.resource) +
                         ", which the graph does not declare");
  const std::size_t n = a.n;
  a.skipped.assign(n, false);
  for (std::size_t i = 0; i < n; ++i) a.skipped[i] = !passes[i].skip_reason.empty();
  a.writers.assign(res.size(), {});
  std::vector<std::vector<std::size_t>> skipped_writers(res.size());
  for (std::size_t i = 0; i < n; ++i)
    for (const auto& acc : passes[i].accesses)
      if (writes(acc.use) && !acc.history) (a.skipped[i] ? skipped_writers : a.writers)[acc.resource].push_back(i);
  a.accesses.assign(n, {});
  for (std::size_t i = 0; i < n; ++i) {
    if (a.skipped[i]) continue;
    for (const PassAccess& acc : passes[i].accesses) {
      const ResourceDecl& r = res[acc.resource];
      const bool needs_writer = reads(acc.use) && !acc.history && r.lifetime != Lifetime::Imported;
      bool has_writer = false;
      for (std::size_t w : a.writers[acc.resource]) has_writer = has_writer || w != i;
      if (needs_writer && !has_writer) {
        if (!skipped_writers[acc.resource].empty()) {
          const auto& w = passes[skipped_writers[acc.resource].front()];
          throw GraphError("pass " + quoted(passes[i].name) + " reads " + quoted(r.name) + ", whose writer " +
                           quoted(w.name) + " is left out (" + w.skip_reason + ")");
        }
        throw GraphError("pass " + quoted(passes[i].name) + " reads " + quoted(r.name) +
                         ", which no pass writes and which is neither a history nor imported");
      }
      a.accesses[i].push_back(acc);
    }
  }
}

// Phase 2, cull: keep what contributes to an output, directly or through a history read next frame.
std::vector<CulledPass> cull(Analysis& a) {
  const std::size_t n = a.n;
  const auto& res = a.res;
  a.live.assign(n, false);
  std::vector<bool> needed(res.size()), history_needed(res.size());
  for (ResourceId o : a.graph.outputs()) needed[o] = true;
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t i = n; i-- > 0;) {
      if (a.skipped[i] || a.live[i]) continue;
      bool contributes = false;
      for (const auto& acc : a.accesses[i])
        if (writes(acc.use) && !acc.history && (needed[acc.resource] || history_needed[acc.resource]))
          contributes = true;
      if (!contributes) continue;
      a.live[i] = changed = true;
      for (const auto& acc : a.accesses[i]) {
        if (acc.history)
          history_needed[acc.resource] = true;
        else if (reads(acc.use))
          needed[acc.resource] = true;
      }
    }
  }
  std::vector<CulledPass> culled;
  for (std::size_t i = 0; i < n; ++i) {
    if (a.skipped[i]) {
      culled.push_back({a.passes[i].name, a.passes[i].skip_reason});
    } else if (!a.live[i]) {
      std::string written;
      for (const auto& acc : a.accesses[i])
        if (writes(acc.use)) written += (written.empty() ? "" : ", ") + quoted(res[acc.resource].name);
      culled.push_back({a.passes[i].name, "nothing that contributes to the frame's outputs reads what it writes (" +
                                              (written.empty() ? std::string("nothing") : written) + ")"});
    }
  }
  return culled;
}

// Phase 3, order: a reader comes after every other writer of what it reads (Kahn, ties by
// declaration); passes that read-modify-write one resource (counters both accumulate into) would
// each come after the other, so among themselves they keep their declaration order. Two writers of
// one resource must then be ordered by a dependency, not by accident of declaration.
void order(Analysis& a) {
  const std::size_t n = a.n;
  const auto& passes = a.passes;
  const auto& res = a.res;
  a.after.assign(n, {});
  std::vector<int> indegree(n);
  for (std::size_t p = 0; p < n; ++p) {
    if (!a.live[p]) continue;
    for (const auto& acc : a.accesses[p]) {
      if (!reads(acc.use) || acc.history) continue;
      for (std::size_t w : a.writers[acc.resource])
        if (w != p && a.live[w] && !(writes(acc.use) && w > p) && a.after[w].insert(p).second) ++indegree[p];
    }
  }
  std::vector<bool> placed(n);
  for (;;) {
    std::size_t next = n;
    for (std::size_t i = 0; i < n && next == n; ++i)
      if (a.live[i] && !placed[i] && indegree[i] == 0) next = i;
    if (next == n) break;
    placed[next] = true;
    a.order.push_back(next);
    for (std::size_t s : a.after[next]) --indegree[s];
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!a.live[i] || placed[i]) continue;
    std::string through;
    for (const auto& acc : a.accesses[i])
      if (reads(acc.use) && !acc.history)
        for (std::size_t w : a.writers[acc.resource])
          if (w != i && a.live[w] && !placed[w] && through.empty())
            through = quoted(passes[w].name) + " through " + quoted(res[acc.resource].name);
    throw GraphError("cycle: pass " + quoted(passes[i].name) + " and " + through + " depend on each other");
  }
  auto reaches = [&](std::size_t from, std::size_t to) {
    std::vector<bool> seen(n);
    std::vector<std::size_t> stack{from};
    while (!stack.empty()) {
      std::size_t v = stack.back();
      stack.pop_back();
      if (v == to) return true;
      for (std::size_t s : a.after[v])
        if (!seen[s]) seen[s] = true, stack.push_back(s);
    }
    return false;
  };
  for (std::size_t r = 0; r < res.size(); ++r) {
    std::vector<std::size_t> w;
    for (std::size_t p : a.writers[r])
      if (a.live[p]) w.push_back(p);
    for (std::size_t x = 0; x < w.size(); ++x)
      for (std::size_t y = x + 1; y < w.size(); ++y)
        if (!reaches(w[x], w[y]) && !reaches(w[y], w[x]))
          throw GraphError("passes " + quoted(passes[w[x]].name) + " and " + quoted(passes[w[y]].name) +
                           " both write " + quoted(res[r].name) + " with no order between them");
  }
}

// The physical resource a barrier tracks: a transient pool slot, one version of a persistent
// resource, or an import.
struct TrackKey {
  Placement::Where where = Placement::Where::Unused;
  std::uint32_t index = 0;    // slot (transient) or resource id (persistent, imported)
  std::uint32_t version = 0;  // persistent only
  friend auto operator<=>(const TrackKey&, const TrackKey&) = default;
};

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
  out.history_valid.assign(res.size(), false);
  out.lifetime.assign(res.size(), {-1, -1});

  Analysis a{graph, passes, res, passes.size(), {}, {}, {}, {}, {}, {}};
  validate(a);
  out.culled = cull(a);
  order(a);
  place(out, a.order, a.accesses);
  derive_barriers(out, a.order, a.accesses);
  return out;
}

// Phase 4, place: lifetimes, transient aliasing (greedy over the pool), persistent ping-pong.
void GraphRuntime::place(CompiledFrame& out, const std::vector<std::size_t>& order,
                         const std::vector<std::vector<PassAccess>>& accesses) {
  const auto& res = out.graph->resources();
  for (std::size_t k = 0; k < order.size(); ++k)
    for (const auto& acc : accesses[order[k]]) {
      auto& life = out.lifetime[acc.resource];
      if (life.first < 0) life.first = static_cast<int>(k);
      life.second = static_cast<int>(k);
    }
  std::vector<ResourceId> transients;
  for (ResourceId r = 0; r < res.size(); ++r) {
    if (out.lifetime[r].first < 0) continue;
    switch (res[r].lifetime) {
      case Lifetime::Transient:
        transients.push_back(r);
        break;
      case Lifetime::Persistent:
        out.placement[r] = {Placement::Where::Persistent, static_cast<std::uint32_t>(frame_ % 2)};
        out.memory.persistent += 2 * bytes(res[r]);
        break;
      case Lifetime::Imported:
        out.placement[r] = {Placement::Where::Imported, 0};
        break;
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
}

// Phase 5, barriers: per physical resource, transition when the state differs, synchronise on
// hazards; then outputs into their final states, and what this frame leaves for the next.
void GraphRuntime::derive_barriers(CompiledFrame& out, const std::vector<std::size_t>& order,
                                   const std::vector<std::vector<PassAccess>>& accesses) {
  const auto& graph = *out.graph;
  const auto& res = graph.resources();
  struct Track {
    hal::State state = hal::State::Undefined;
    bool written = false, pending_write = false, pending_read = false, fresh = false;
    ResourceId owner = 0;  // transients: the resource that last used the slot
    bool owned = false;
  };
  std::map<TrackKey, Track> tracks;
  std::vector<bool> cleared(res.size(), false);  // histories cleared this frame: they hold zeros
  auto key = [&](ResourceId r, bool history) -> TrackKey {
    const Placement& p = out.placement[r];
    switch (p.where) {
      case Placement::Where::Transient:
        return {p.where, p.slot, 0};  // shared by its owners
      case Placement::Where::Persistent:
        return {p.where, r, history ? 1 - p.slot : p.slot};
      default:
        return {p.where, r, 0};
    }
  };
  auto track_of = [&](ResourceId r, bool history) -> Track& {
    const TrackKey k = key(r, history);
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
      if (pit != persistent_.end() &&
          same_shape(Slot{res[r].kind, res[r].width, res[r].height, res[r].format, res[r].size, {}},
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
        cleared[m.resource] = true;
      }
      if (m.history) out.history_valid[m.resource] = !cleared[m.resource];
      const bool hazard = t.pending_write || (m.write && t.pending_read);
      if (t.fresh || t.state != m.needs || hazard) {
        // Taking over a slot: from Undefined when nothing used it, else wait for the old owner and
        // discard its contents.
        cp.barriers.push_back({m.resource, m.history, t.state, m.needs, t.fresh && t.state != hal::State::Undefined});
        t.state = m.needs;
        t.pending_write = t.pending_read = t.fresh = false;
      }
      if (m.write)
        t.pending_write = true, t.pending_read = false, t.written = true;
      else
        t.pending_read = true;
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
    if (k.where == Placement::Where::Transient)
      out.slot_end.push_back({k.index, t.state, t.pending_write || t.pending_read});
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
}

}  // namespace asvgf::graph
