// hal_record/record_device.hpp: a HAL device with no GPU that records commands and checks ordering.
//
// RecordDevice implements hal::Device. Nothing executes: buffers and images hold no data (reads
// return zeros, timers are unavailable). What it does instead, at submit(), in submission order:
//   - keeps a printable log of every command, with the resources it reads and writes (dispatches
//     take these from the shader reflection's per-binding access);
//   - tracks every resource's hal::State and its unsynchronised accesses since the last barrier;
//   - reports (never throws) ordering mistakes, naming both commands by debug-label path and the
//     resource: read-after-write, write-after-read and write-after-write with no barrier between;
//     a barrier whose `before` is not the tracked state; a use in the wrong state; a use of a
//     destroyed resource; a read of a resource nothing has written.
// Calls that break the interface contract itself (binding name that the shader does not have,
// wrong uniform size, unbound binding, wrong usage) are the validation layer's to refuse
// (hal/validate.hpp): use this device behind hal::validate::wrap, as every caller in the project
// does. On its own it only throws InvalidHandle for handles it never created.
//
// Thread safety: like every hal::Device, externally synchronised.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "hal/device.hpp"

namespace hal::record {

enum class ReportKind {
  ReadAfterWrite,
  WriteAfterRead,
  WriteAfterWrite,
  BarrierStateMismatch,  // barrier.before differs from the tracked state
  WrongState,            // a command uses a resource in a state it cannot use it in
  UseOfDestroyed,
  ReadBeforeWrite,       // read of a resource nothing has written (or whose contents were discarded)
};
std::string_view to_string(ReportKind kind);

struct Report {
  ReportKind kind;
  std::string resource;        // debug name of the resource
  std::string first_command;   // the earlier command involved ("" when there is none)
  std::string second_command;  // the command where the problem shows
  std::string message;         // one readable sentence with all of the above
};

// One line of the log: a command as submitted.
struct LogEntry {
  std::size_t index = 0;       // position in submission order, from 0
  std::string name;            // "label/path: op object", as used in reports
  std::vector<std::string> reads;   // debug names of resources read
  std::vector<std::string> writes;  // debug names of resources written
  std::string text;            // the printed line
};

struct RecordOptions {
  Capabilities capabilities = default_capabilities();
  // Off: record and track states but report nothing (used to show tests depend on the checks).
  bool checks = true;

  static Capabilities default_capabilities();
};

class RecordDevice final : public Device {
 public:
  explicit RecordDevice(RecordOptions options = {});
  ~RecordDevice() override;

  // What it found so far; clear_reports() empties the list (the log and states stay).
  const std::vector<Report>& reports() const;
  void clear_reports();
  const std::vector<LogEntry>& log() const;
  std::string log_text() const;  // every LogEntry::text, one per line
  State state_of(Resource resource) const;
  std::string name_of(Resource resource) const;

  // hal::Device
  const AdapterInfo& adapter() const override;
  const Capabilities& capabilities() const override;
  BufferHandle create_buffer(const BufferDesc& desc) override;
  ImageHandle create_image(const ImageDesc& desc) override;
  PipelineHandle create_pipeline(const ComputePipelineDesc& desc) override;
  BindingSetHandle create_binding_set(const BindingSetDesc& desc) override;
  AccelHandle create_blas(const BlasDesc& desc) override;
  AccelHandle create_tlas(const TlasDesc& desc) override;
  TimerQueriesHandle create_timer_queries(const TimerQueriesDesc& desc) override;
  std::unique_ptr<CommandList> create_command_list(std::string_view name) override;
  void destroy(BufferHandle handle) override;
  void destroy(ImageHandle handle) override;
  void destroy(PipelineHandle handle) override;
  void destroy(BindingSetHandle handle) override;
  void destroy(AccelHandle handle) override;
  void destroy(TimerQueriesHandle handle) override;
  void submit(CommandList& commands) override;
  void wait() override;
  void upload_buffer(BufferHandle dst, std::uint64_t offset, std::span<const std::byte> data) override;
  void read_buffer(BufferHandle src, std::uint64_t offset, std::span<std::byte> out) override;
  void upload_image(ImageHandle dst, std::span<const std::byte> data) override;
  void read_image(ImageHandle src, std::span<std::byte> out) override;
  std::vector<std::optional<double>> read_timers(TimerQueriesHandle timers) override;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace hal::record
