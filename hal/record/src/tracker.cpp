// Replaying submitted commands: resource states, unsynchronised accesses and the reports.
#include <algorithm>
#include <string>

#include "impl.hpp"

namespace hal::record {
namespace {

std::string quoted(const std::string& s) { return "'" + s + "'"; }

// Folds several uses of one resource in one command (two bindings of one buffer) into one.
std::vector<CommandUse> merge_uses(std::vector<CommandUse> uses) {
  std::vector<CommandUse> merged;
  for (auto& u : uses) {
    auto it = std::find_if(merged.begin(), merged.end(), [&](const CommandUse& m) { return m.resource == u.resource; });
    if (it == merged.end()) {
      merged.push_back(std::move(u));
      continue;
    }
    it->read = it->read || u.read;
    if (u.write && !it->write) {
      it->write = true;
      it->needs = u.needs;  // a write needs the write state
      it->role = u.role;
    }
  }
  return merged;
}

}  // namespace

void RecordDevice::Impl::report(ReportKind kind, std::string resource, std::string first, std::string second,
                                std::string message) {
  if (!options.checks) return;
  reports.push_back({kind, std::move(resource), std::move(first), std::move(second), std::move(message)});
}

std::vector<CommandUse> RecordDevice::Impl::dispatch_uses(const Command& command) {
  std::vector<CommandUse> uses;
  auto& set = binding_set(command.dispatch.bindings);
  auto& pipe = pipeline(command.dispatch.pipeline);
  if (set.destroyed)
    report(ReportKind::UseOfDestroyed, set.name, "", command.name,
           command.name + " uses binding set " + quoted(set.name) + " after it was destroyed");
  if (pipe.destroyed)
    report(ReportKind::UseOfDestroyed, pipe.name, "", command.name,
           command.name + " uses pipeline " + quoted(pipe.name) + " after it was destroyed");
  const auto& bindings = pipe.shader->bindings;
  for (std::size_t i = 0; i < bindings.size(); ++i) {
    const ShaderBinding& b = bindings[i];
    if (b.kind == BindingKind::UniformBuffer) continue;  // bound implicitly from DispatchDesc::uniforms
    if (!set.bound[i]) continue;  // the validation layer refuses such a dispatch
    CommandUse u;
    u.resource = *set.bound[i];
    u.read = b.access != Access::Write;
    u.write = b.access != Access::Read;
    u.needs = b.kind == BindingKind::AccelerationStructure ? State::AccelRead
              : u.write                                    ? State::ShaderWrite
                                                           : State::ShaderRead;
    u.role = "binding " + quoted(std::string(b.name));
    uses.push_back(std::move(u));
  }
  return uses;
}

void RecordDevice::Impl::apply_barriers(const Command& command) {
  for (const Barrier& b : command.barriers) {
    const std::string name = name_of(b.resource);
    if (destroyed(b.resource)) {
      report(ReportKind::UseOfDestroyed, name, "", command.name,
             command.name + " names " + quoted(name) + " after it was destroyed");
      continue;
    }
    SimulatedState& t = track(b.resource);
    // A barrier from Undefined is always allowed: it discards the contents.
    if (b.before != State::Undefined && b.before != t.state)
      report(ReportKind::BarrierStateMismatch, name, t.last_change, command.name,
             command.name + " moves " + quoted(name) + " from " + std::string(to_string(b.before)) +
                 " but it is in " + std::string(to_string(t.state)) +
                 (t.last_change.empty() ? std::string() : " (set by " + t.last_change + ")"));
    // A barrier from Undefined has no source scope: it waits for nothing that came before.
    if (b.before == State::Undefined && !t.pending_write.empty())
      report(ReportKind::WriteAfterWrite, name, t.pending_write, command.name,
             "write-after-write hazard on " + quoted(name) + ": " + command.name +
                 " discards it from undefined without waiting for " + t.pending_write + ", which wrote it");
    if (b.before == State::Undefined)
      for (const auto& reader : t.pending_reads)
        report(ReportKind::WriteAfterRead, name, reader, command.name,
               "write-after-read hazard on " + quoted(name) + ": " + command.name +
                   " discards it from undefined without waiting for " + reader + ", which read it");
    if (b.before == State::Undefined || b.discard) t.written = false;
    t.state = b.after;
    t.last_change = command.name;
    t.pending_write.clear();
    t.pending_reads.clear();
  }
}

void RecordDevice::Impl::apply_uses(const Command& command) {
  for (const CommandUse& u : command.uses) {
    const std::string name = name_of(u.resource);
    if (destroyed(u.resource)) {
      report(ReportKind::UseOfDestroyed, name, "", command.name,
             command.name + " uses " + quoted(name) + " (" + u.role + ") after it was destroyed");
      continue;
    }
    SimulatedState& t = track(u.resource);
    if (t.state != u.needs)
      report(ReportKind::WrongState, name, t.last_change, command.name,
             command.name + " needs " + quoted(name) + " (" + u.role + ") in " + std::string(to_string(u.needs)) +
                 " but it is in " + std::string(to_string(t.state)) +
                 (t.last_change.empty() ? std::string() : " (set by " + t.last_change + ")"));
    if (u.read && !t.written)
      report(ReportKind::ReadBeforeWrite, name, "", command.name,
             command.name + " reads " + quoted(name) + " (" + u.role + ") but nothing has written it");
    if (u.read && !t.pending_write.empty())
      report(ReportKind::ReadAfterWrite, name, t.pending_write, command.name,
             "read-after-write hazard on " + quoted(name) + ": " + command.name + " reads it after " +
                 t.pending_write + " wrote it, with no barrier between");
    if (u.write && !t.pending_write.empty())
      report(ReportKind::WriteAfterWrite, name, t.pending_write, command.name,
             "write-after-write hazard on " + quoted(name) + ": " + command.name + " writes it after " +
                 t.pending_write + " wrote it, with no barrier between");
    if (u.write)
      for (const auto& reader : t.pending_reads)
        report(ReportKind::WriteAfterRead, name, reader, command.name,
               "write-after-read hazard on " + quoted(name) + ": " + command.name + " writes it after " + reader +
                   " read it, with no barrier between");
  }
  for (const CommandUse& u : command.uses) {
    if (destroyed(u.resource)) continue;
    SimulatedState& t = track(u.resource);
    if (u.write) {
      t.pending_write = command.name;
      t.pending_reads.clear();
      t.written = true;
    } else if (u.read) {
      t.pending_reads.push_back(command.name);
    }
  }
}

void RecordDevice::Impl::replay(Command& command) {
  if (command.op == Command::Op::Dispatch) {
    command.uses = dispatch_uses(command);
  }
  command.uses = merge_uses(std::move(command.uses));
  apply_barriers(command);
  apply_uses(command);
  append_log(command);
}

void RecordDevice::Impl::append_log(const Command& command) {
  LogEntry e;
  e.index = log.size();
  e.name = command.name;
  for (const CommandUse& u : command.uses) {
    if (u.read) e.reads.push_back(name_of(u.resource));
    if (u.write) e.writes.push_back(name_of(u.resource));
  }
  e.text = "#" + std::to_string(e.index) + " " + e.name;
  auto list = [](const std::vector<std::string>& names) {
    std::string s;
    for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
    return s;
  };
  if (!e.reads.empty()) e.text += "  reads [" + list(e.reads) + "]";
  if (!e.writes.empty()) e.text += "  writes [" + list(e.writes) + "]";
  log.push_back(std::move(e));
}

void RecordDevice::Impl::host_access(Resource r, bool write, std::string_view what) {
  const std::string name = name_of(r);
  const std::string command = std::string(what) + " " + name;
  Command c;
  c.name = command;
  if (destroyed(r)) {
    report(ReportKind::UseOfDestroyed, name, "", command, command + " after it was destroyed");
    append_log(c);
    return;
  }
  SimulatedState& t = track(r);
  if (write) {
    t.state = State::CopyDst;
    t.written = true;
    t.last_change = command;
    c.uses.push_back({r, false, true, State::CopyDst, "host upload"});
  } else {
    if (t.state != State::CopySrc)
      report(ReportKind::WrongState, name, t.last_change, command,
             command + " needs " + quoted(name) + " in copy-src but it is in " + std::string(to_string(t.state)));
    if (!t.written)
      report(ReportKind::ReadBeforeWrite, name, "", command, command + " but nothing has written " + quoted(name));
    c.uses.push_back({r, true, false, State::CopySrc, "host readback"});
  }
  // The device waits for all work around a host transfer, so nothing stays unsynchronised.
  t.pending_write.clear();
  t.pending_reads.clear();
  append_log(c);
}

}  // namespace hal::record
