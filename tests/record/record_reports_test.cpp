// Each kind of recording-HAL report: a minimal program that triggers it, and a correct twin that
// reports nothing. Reports must name the resource and both commands (by debug-label path).
// Contract errors (unknown binding names, wrong usage, unbound bindings) are the validation
// layer's and are tested once for every backend in tests/conformance/contract_test.cpp.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <set>

#include "hal/error.hpp"
#include "checked_record.hpp"
#include "hal_record/record_device.hpp"
#include "test_shaders.hpp"

using namespace hal;
using hal::record::RecordDevice;
using hal::record::ReportKind;

namespace {

constexpr auto kAllBufferUsage =
    BufferUsage::Storage | BufferUsage::CopySrc | BufferUsage::CopyDst | BufferUsage::AccelBuildInput;

struct Fixture : CheckedRecord {
  std::unique_ptr<CommandList> cmd = device.create_command_list("test");
  PipelineHandle copy = device.create_pipeline({"copy", &record_test::kCopyShader});
  PipelineHandle in_place = device.create_pipeline({"in_place", &record_test::kInPlaceShader});

  BufferHandle buffer(const char* name, BufferUsage usage = kAllBufferUsage) {
    return device.create_buffer({name, 256, usage});
  }
  // A buffer with contents, left in `state`.
  BufferHandle written_buffer(const char* name, State state) {
    auto b = buffer(name);
    std::array<std::byte, 16> data{};
    device.upload_buffer(b, 0, data);
    if (state != State::CopyDst) {
      cmd->barrier({b, State::CopyDst, state});
      submit();
    }
    return b;
  }
  BindingSetHandle copy_set(BufferHandle src, BufferHandle dst) {
    return device.create_binding_set({"copy_set", copy, {{"src", src}, {"dst", dst}}});
  }
  void dispatch(const char* label, PipelineHandle pipeline, BindingSetHandle set) {
    cmd->begin_label(label);
    cmd->dispatch({pipeline, set});
    cmd->end_label();
  }
  void submit() {
    device.submit(*cmd);
    device.wait();
    cmd->reset();
  }
  std::set<ReportKind> kinds() const {
    std::set<ReportKind> k;
    for (const auto& r : record.reports()) k.insert(r.kind);
    return k;
  }
  const record::Report* find(ReportKind kind) const {
    for (const auto& r : record.reports())
      if (r.kind == kind) return &r;
    return nullptr;
  }
  std::string all_messages() const {
    std::string s;
    for (const auto& r : record.reports()) s += r.message + "\n";
    return s;
  }
};

}  // namespace

TEST_CASE("read-after-write without a barrier is reported naming writer, reader and resource") {
  for (bool with_barrier : {false, true}) {
    CAPTURE(with_barrier);
    Fixture f;
    auto a = f.written_buffer("input", State::ShaderRead);
    auto b = f.written_buffer("middle", State::ShaderWrite);
    auto c = f.written_buffer("output", State::ShaderWrite);
    f.dispatch("producer", f.copy, f.copy_set(a, b));
    if (with_barrier) f.cmd->barrier({b, State::ShaderWrite, State::ShaderRead});
    // Without the barrier the reader sees `middle` in shader-write: read it through a read-write
    // binding so that the only thing wrong is the missing synchronisation.
    auto set = with_barrier ? f.copy_set(b, c)
                            : f.device.create_binding_set({"rw", f.in_place, {{"data", b}}});
    f.dispatch("consumer", with_barrier ? f.copy : f.in_place, set);
    f.submit();
    if (with_barrier) {
      CHECK_MESSAGE(f.record.reports().empty(), f.all_messages());
    } else {
      const auto* r = f.find(ReportKind::ReadAfterWrite);
      REQUIRE_MESSAGE(r != nullptr, f.all_messages());
      CHECK(r->resource == "middle");
      CHECK(r->first_command == "producer: dispatch copy");
      CHECK(r->second_command == "consumer: dispatch in_place");
      CHECK(r->message.find("read-after-write") != std::string::npos);
    }
  }
}

TEST_CASE("write-after-read without a barrier is reported") {
  for (bool with_barrier : {false, true}) {
    CAPTURE(with_barrier);
    Fixture f;
    auto a = f.written_buffer("shared", State::ShaderRead);
    auto b = f.written_buffer("first_out", State::ShaderWrite);
    f.dispatch("reader", f.copy, f.copy_set(a, b));
    if (with_barrier) f.cmd->barrier({a, State::ShaderRead, State::ShaderWrite});
    auto c = f.written_buffer("second_in", State::ShaderRead);
    f.dispatch("writer", f.copy, f.copy_set(c, a));
    f.submit();
    if (with_barrier) {
      CHECK_MESSAGE(f.record.reports().empty(), f.all_messages());
    } else {
      const auto* r = f.find(ReportKind::WriteAfterRead);
      REQUIRE_MESSAGE(r != nullptr, f.all_messages());
      CHECK(r->resource == "shared");
      CHECK(r->first_command == "reader: dispatch copy");
      CHECK(r->second_command == "writer: dispatch copy");
    }
  }
}

TEST_CASE("write-after-write without a barrier is reported, and only that") {
  for (bool with_barrier : {false, true}) {
    CAPTURE(with_barrier);
    Fixture f;
    auto a = f.written_buffer("in", State::ShaderRead);
    auto b = f.written_buffer("out", State::ShaderWrite);
    f.dispatch("first", f.copy, f.copy_set(a, b));
    if (with_barrier) f.cmd->barrier({b, State::ShaderWrite, State::ShaderWrite});
    f.dispatch("second", f.copy, f.copy_set(a, b));
    f.submit();
    if (with_barrier) {
      CHECK_MESSAGE(f.record.reports().empty(), f.all_messages());
    } else {
      CHECK(f.kinds() == std::set{ReportKind::WriteAfterWrite});
      const auto* r = f.find(ReportKind::WriteAfterWrite);
      REQUIRE(r != nullptr);
      CHECK(r->first_command == "first: dispatch copy");
      CHECK(r->second_command == "second: dispatch copy");
      CHECK(r->resource == "out");
    }
  }
}

TEST_CASE("a barrier whose before-state is not the tracked state is reported") {
  for (bool correct : {false, true}) {
    CAPTURE(correct);
    Fixture f;
    auto b = f.written_buffer("history", State::ShaderWrite);
    f.cmd->begin_label("transition");
    f.cmd->barrier({b, correct ? State::ShaderWrite : State::CopyDst, State::ShaderRead});
    f.cmd->end_label();
    f.submit();
    if (correct) {
      CHECK_MESSAGE(f.record.reports().empty(), f.all_messages());
    } else {
      CHECK(f.kinds() == std::set{ReportKind::BarrierStateMismatch});
      const auto* r = f.find(ReportKind::BarrierStateMismatch);
      REQUIRE(r != nullptr);
      CHECK(r->resource == "history");
      CHECK(r->second_command.find("transition: barrier") == 0);
      CHECK(r->first_command.find("barrier") != std::string::npos);  // the barrier that set shader-write
      CHECK(r->message.find("copy-dst") != std::string::npos);
      CHECK(r->message.find("shader-write") != std::string::npos);
    }
  }
}

TEST_CASE("using a resource in a state the command cannot use is reported") {
  for (bool correct : {false, true}) {
    CAPTURE(correct);
    Fixture f;
    auto a = f.written_buffer("uploaded", State::CopyDst);  // upload leaves copy-dst
    auto b = f.written_buffer("out", State::ShaderWrite);
    if (correct) f.cmd->barrier({a, State::CopyDst, State::ShaderRead});
    f.dispatch("use", f.copy, f.copy_set(a, b));
    f.submit();
    if (correct) {
      CHECK_MESSAGE(f.record.reports().empty(), f.all_messages());
    } else {
      CHECK(f.kinds() == std::set{ReportKind::WrongState});
      CHECK(f.record.reports().front().message.find("'uploaded'") != std::string::npos);
    }
  }
}

TEST_CASE("use of a destroyed resource is reported") {
  for (bool destroy : {true, false}) {
    CAPTURE(destroy);
    Fixture f;
    auto a = f.written_buffer("in", State::ShaderRead);
    auto b = f.written_buffer("gone", State::ShaderWrite);
    auto set = f.copy_set(a, b);
    f.dispatch("late", f.copy, set);
    if (destroy) f.device.destroy(b);
    f.submit();
    if (destroy) {
      CHECK(f.kinds() == std::set{ReportKind::UseOfDestroyed});
      CHECK(f.record.reports().front().resource == "gone");
      CHECK(f.record.reports().front().second_command == "late: dispatch copy");
    } else {
      CHECK_MESSAGE(f.record.reports().empty(), f.all_messages());
    }
  }
}

TEST_CASE("a read of a resource nothing has written is reported") {
  for (bool write_first : {false, true}) {
    CAPTURE(write_first);
    Fixture f;
    auto a = f.buffer("never_written");
    auto b = f.written_buffer("out", State::ShaderWrite);
    if (write_first) {
      std::array<std::byte, 4> data{};
      f.device.upload_buffer(a, 0, data);
      f.cmd->barrier({a, State::CopyDst, State::ShaderRead});
    } else {
      f.cmd->barrier({a, State::Undefined, State::ShaderRead});
    }
    f.dispatch("reader", f.copy, f.copy_set(a, b));
    f.submit();
    if (write_first) {
      CHECK_MESSAGE(f.record.reports().empty(), f.all_messages());
    } else {
      CHECK(f.kinds() == std::set{ReportKind::ReadBeforeWrite});
      CHECK(f.record.reports().front().resource == "never_written");
    }
  }
}

TEST_CASE("image dispatches track sampled reads and storage writes") {
  Fixture f;
  auto pipe = f.device.create_pipeline({"filter", &record_test::kImageShader});
  auto in = f.device.create_image({"color", 8, 8, Format::RGBA16F, ImageUsage::Sampled | ImageUsage::CopyDst});
  auto out = f.device.create_image({"filtered", 8, 8, Format::RGBA16F, ImageUsage::Storage | ImageUsage::Sampled});
  std::array<std::byte, 8 * 8 * 8> texels{};
  f.device.upload_image(in, texels);
  auto set = f.device.create_binding_set({"filter_set", pipe, {{"src_image", in}, {"dst_image", out}}});
  std::array<std::byte, 16> params{};
  f.cmd->barrier({{in, State::CopyDst, State::ShaderRead}, {out, State::Undefined, State::ShaderWrite}});
  f.cmd->dispatch({pipe, set, params, 1, 1, 1});
  f.submit();
  CHECK_MESSAGE(f.record.reports().empty(), f.all_messages());
  REQUIRE(f.record.log().size() >= 2);
  const auto& last = f.record.log().back();
  CHECK(last.reads == std::vector<std::string>{"color"});
  CHECK(last.writes == std::vector<std::string>{"filtered"});
  CHECK(f.record.state_of(out) == State::ShaderWrite);
}

TEST_CASE("the log prints every command with its label path, reads and writes") {
  Fixture f;
  auto a = f.written_buffer("lit", State::ShaderRead);
  auto b = f.written_buffer("blurred", State::ShaderWrite);
  f.cmd->begin_label("frame 3");
  f.dispatch("atrous", f.copy, f.copy_set(a, b));
  f.cmd->end_label();
  f.submit();
  const std::string text = f.record.log_text();
  CHECK(text.find("frame 3/atrous: dispatch copy  reads [lit]  writes [blurred]") != std::string::npos);
  CHECK(text.find("upload lit") != std::string::npos);
}
