// Seeded random programs of dispatches and copies over a few buffers and images. Barriers are
// placed by a simple reference rule (before a use: transition when the state differs, or
// synchronise when the access would race with an unsynchronised earlier one). Such programs must
// never report; every barrier the rule places is required, so removing any single one must report.
#include <doctest/doctest.h>

#include <array>
#include <cstddef>
#include <random>
#include <string>
#include <vector>

#include "checked_record.hpp"
#include "hal_record/record_device.hpp"
#include "test_shaders.hpp"

using namespace hal;
using hal::record::RecordDevice;
using hal::record::RecordOptions;

namespace {

constexpr int kBuffers = 3;
constexpr int kImages = 2;

struct Access {
  int resource;  // 0..kBuffers-1 buffers, then images
  bool write;
  State needs;
};

// One step: either one barrier or one command touching a few resources.
struct Step {
  bool is_barrier = false;
  int resource = 0;  // for barriers
  State before = State::Undefined, after = State::Undefined;
  enum class Kind { CopyDispatch, ImageDispatch, CopyBuffer, CopyImage } kind = Kind::CopyDispatch;
  int a = 0, b = 0;  // source, destination
};

std::vector<Access> accesses(const Step& s) {
  switch (s.kind) {
    case Step::Kind::CopyDispatch:
    case Step::Kind::ImageDispatch:
      return {{s.a, false, State::ShaderRead}, {s.b, true, State::ShaderWrite}};
    case Step::Kind::CopyBuffer:
    case Step::Kind::CopyImage:
      return {{s.a, false, State::CopySrc}, {s.b, true, State::CopyDst}};
  }
  return {};
}

// The reference rule, applied while generating: returns commands with their required barriers.
std::vector<Step> generate(std::uint32_t seed, int length) {
  std::mt19937 rng(seed);
  struct Sim {
    State state = State::CopyDst;  // every resource starts uploaded
    bool written = false, read = false;
  };
  std::array<Sim, kBuffers + kImages> sim{};
  std::vector<Step> steps;
  auto pick_two = [&](int first, int count) {
    int a = first + static_cast<int>(rng() % count);
    int b = first + static_cast<int>(rng() % (count - 1));
    if (b >= a) ++b;
    return std::pair{a, b};
  };
  for (int i = 0; i < length; ++i) {
    Step cmd;
    cmd.kind = static_cast<Step::Kind>(rng() % 4);
    const bool images = cmd.kind == Step::Kind::ImageDispatch || cmd.kind == Step::Kind::CopyImage;
    std::tie(cmd.a, cmd.b) = images ? pick_two(kBuffers, kImages) : pick_two(0, kBuffers);
    for (const Access& acc : accesses(cmd)) {
      Sim& s = sim[acc.resource];
      const bool hazard = s.written || (acc.write && s.read);
      if (s.state != acc.needs || hazard) {
        Step barrier;
        barrier.is_barrier = true;
        barrier.resource = acc.resource;
        barrier.before = s.state;
        barrier.after = acc.needs;
        steps.push_back(barrier);
        s = Sim{acc.needs, false, false};
      }
    }
    for (const Access& acc : accesses(cmd)) {
      Sim& s = sim[acc.resource];
      if (acc.write)
        s.written = true, s.read = false;
      else
        s.read = true;
    }
    steps.push_back(cmd);
  }
  return steps;
}

// Runs the program on a fresh recording device, leaving out step `skip` (-1: none).
std::size_t run(const std::vector<Step>& steps, int skip, bool checks = true) {
  RecordOptions options;
  options.checks = checks;
  CheckedRecord checked(options);
  hal::Device& device = checked.device;
  std::vector<Resource> resources;
  for (int i = 0; i < kBuffers; ++i)
    resources.push_back(device.create_buffer(
        {"buf" + std::to_string(i), 64, BufferUsage::Storage | BufferUsage::CopySrc | BufferUsage::CopyDst}));
  for (int i = 0; i < kImages; ++i)
    resources.push_back(
        device.create_image({"img" + std::to_string(i), 4, 4, Format::RGBA16F,
                             ImageUsage::Sampled | ImageUsage::Storage | ImageUsage::CopySrc | ImageUsage::CopyDst}));
  std::array<std::byte, 4 * 4 * 8> data{};
  for (int i = 0; i < kBuffers; ++i) device.upload_buffer(BufferHandle{resources[i].id}, 0, std::span(data).first(64));
  for (int i = 0; i < kImages; ++i) device.upload_image(ImageHandle{resources[kBuffers + i].id}, data);

  auto copy = device.create_pipeline({"copy", &record_test::kCopyShader});
  auto filter = device.create_pipeline({"filter", &record_test::kImageShader});
  auto cmd = device.create_command_list("random");
  const std::array<std::byte, 16> params{};
  for (int i = 0; i < static_cast<int>(steps.size()); ++i) {
    if (i == skip) continue;
    const Step& s = steps[i];
    cmd->begin_label("step " + std::to_string(i));
    if (s.is_barrier) {
      cmd->barrier({resources[s.resource], s.before, s.after});
    } else {
      const Resource a = resources[s.a], b = resources[s.b];
      switch (s.kind) {
        case Step::Kind::CopyDispatch:
          cmd->dispatch({copy, device.create_binding_set({"set", copy, {{"src", a}, {"dst", b}}})});
          break;
        case Step::Kind::ImageDispatch:
          cmd->dispatch(
              {filter, device.create_binding_set({"set", filter, {{"src_image", a}, {"dst_image", b}}}), params});
          break;
        case Step::Kind::CopyBuffer:
          cmd->copy_buffer({BufferHandle{a.id}, BufferHandle{b.id}, 0, 0, 64});
          break;
        case Step::Kind::CopyImage:
          cmd->copy_image(ImageHandle{a.id}, ImageHandle{b.id});
          break;
      }
    }
    cmd->end_label();
  }
  device.submit(*cmd);
  device.wait();
  return checked.record.reports().size();
}

}  // namespace

TEST_CASE("random programs with reference-rule barriers never report, removing any one barrier always reports") {
  int programs = 0, removals = 0;
  for (std::uint32_t seed = 1; seed <= 60; ++seed) {
    CAPTURE(seed);
    const auto steps = generate(seed, 24);
    REQUIRE(run(steps, -1) == 0);
    ++programs;
    for (int i = 0; i < static_cast<int>(steps.size()); ++i) {
      if (!steps[i].is_barrier) continue;
      CAPTURE(i);
      CHECK(run(steps, i) > 0);
      ++removals;
    }
  }
  MESSAGE(programs << " programs, " << removals << " single-barrier removals checked");
  CHECK(removals > programs);  // the generator does place barriers
}

TEST_CASE("with the checks switched off the same barrier removals report nothing") {
  // Shows that the test above fails through the checker and not through some other effect.
  const auto steps = generate(7, 24);
  for (int i = 0; i < static_cast<int>(steps.size()); ++i)
    if (steps[i].is_barrier) CHECK(run(steps, i, /*checks=*/false) == 0);
}
