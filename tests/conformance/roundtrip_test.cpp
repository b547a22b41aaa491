// Host transfers and copy commands keep every format's bits.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "backends.hpp"
#include "data.hpp"

using namespace conformance;
using hal::Format;
using hal::State;

TEST_CASE("conformance: buffer upload, copy, clear and readback") {
  for_each_backend([](hal::Device& device) {
    const auto usage = hal::BufferUsage::Storage | hal::BufferUsage::CopySrc | hal::BufferUsage::CopyDst;
    const auto a = device.create_buffer({"roundtrip a", 4096, usage});
    const auto b = device.create_buffer({"roundtrip b", 4096, usage});
    const auto data = random_texels(Format::R32Uint, 1024, 1);
    device.upload_buffer(a, 0, data);
    device.upload_buffer(b, 0, data);

    auto cmd = device.create_command_list("roundtrip");
    cmd->barrier({a, State::CopyDst, State::CopySrc});
    cmd->copy_buffer({a, b, 100, 2000, 1000});
    cmd->barrier({b, State::CopyDst, State::CopySrc});
    device.submit(*cmd);
    device.wait();

    std::vector<std::byte> out(4096);
    device.read_buffer(b, 0, out);
    std::vector<std::byte> expected = data;
    std::copy(data.begin() + 100, data.begin() + 1100, expected.begin() + 2000);
    CHECK(out == expected);
    std::vector<std::byte> middle(16);
    device.read_buffer(a, 40, middle);
    CHECK(std::equal(middle.begin(), middle.end(), data.begin() + 40));

    // Partial upload at an offset, then a clear of the other buffer.
    const auto patch = random_texels(Format::R32Uint, 8, 2);
    cmd->reset();
    cmd->barrier({a, State::CopySrc, State::CopyDst});
    device.submit(*cmd);
    device.wait();
    device.upload_buffer(a, 64, patch);
    cmd->reset();
    cmd->barrier({a, State::CopyDst, State::CopySrc});
    cmd->barrier({b, State::CopySrc, State::CopyDst});
    cmd->clear_buffer(b, 0xdeadbeefu);
    cmd->barrier({b, State::CopyDst, State::CopySrc});
    device.submit(*cmd);
    device.wait();
    device.read_buffer(a, 0, out);
    expected = data;
    std::copy(patch.begin(), patch.end(), expected.begin() + 64);
    CHECK(out == expected);
    device.read_buffer(b, 0, out);
    std::vector<std::uint32_t> words(1024);
    std::memcpy(words.data(), out.data(), out.size());
    CHECK(std::all_of(words.begin(), words.end(), [](std::uint32_t w) { return w == 0xdeadbeefu; }));
  });
}

TEST_CASE("conformance: image round trips for every format") {
  for_each_backend([](hal::Device& device) {
    constexpr std::uint32_t w = 13, h = 7;  // odd sizes catch row-pitch mistakes
    for (const Format format : hal::kAllFormats) {
      const std::string name(hal::format_name(format));
      CAPTURE(name);
      const auto usage = hal::ImageUsage::Sampled | hal::ImageUsage::CopySrc | hal::ImageUsage::CopyDst;
      hal::ImageHandle a, b;
      try {
        a = device.create_image({"roundtrip " + name + " a", w, h, format, usage});
        b = device.create_image({"roundtrip " + name + " b", w, h, format, usage});
      } catch (const hal::Error& e) {
        // A device may lack a format; then it must say so as Unsupported, naming the image.
        CHECK(e.kind() == hal::ErrorKind::Unsupported);
        CHECK(e.object().find(name) != std::string::npos);
        MESSAGE("format " << name << " unsupported: " << e.what());
        continue;
      }
      const std::uint64_t bytes = std::uint64_t{w} * h * hal::format_size(format);
      const auto data = random_texels(format, w * h, static_cast<std::uint32_t>(format));
      const auto buffer_usage = hal::BufferUsage::CopySrc | hal::BufferUsage::CopyDst;
      const auto src = device.create_buffer({"roundtrip " + name + " src", bytes, buffer_usage});
      const auto dst = device.create_buffer({"roundtrip " + name + " dst", bytes, buffer_usage});

      // Host → image → host.
      device.upload_image(a, data);
      auto cmd = device.create_command_list("roundtrip " + name);
      cmd->barrier({a, State::CopyDst, State::CopySrc});
      device.submit(*cmd);
      device.wait();
      std::vector<std::byte> out(bytes);
      device.read_image(a, out);
      CHECK(out == data);

      // Host → buffer → image → image → buffer → host, through copy commands.
      device.upload_buffer(src, 0, data);
      cmd->reset();
      cmd->barrier({src, State::CopyDst, State::CopySrc});
      cmd->barrier({a, State::CopySrc, State::CopyDst});
      cmd->copy_buffer_to_image(src, a);
      cmd->barrier({a, State::CopyDst, State::CopySrc});
      cmd->barrier({b, State::Undefined, State::CopyDst});
      cmd->copy_image(a, b);
      cmd->barrier({b, State::CopyDst, State::CopySrc});
      cmd->barrier({dst, State::Undefined, State::CopyDst});
      cmd->copy_image_to_buffer(b, dst);
      cmd->barrier({dst, State::CopyDst, State::CopySrc});
      device.submit(*cmd);
      device.wait();
      std::fill(out.begin(), out.end(), std::byte{0});
      device.read_buffer(dst, 0, out);
      CHECK(out == data);

      // Clear: every texel the converted value.
      cmd->reset();
      cmd->barrier({b, State::CopySrc, State::CopyDst});
      cmd->clear_image(b, {1.0f, 0.5f, 0.25f, 3.0f});
      cmd->barrier({b, State::CopyDst, State::CopySrc});
      device.submit(*cmd);
      device.wait();
      device.read_image(b, out);
      const std::uint32_t channels = hal::format_channels(format);
      const std::uint32_t channel_size = hal::format_size(format) / channels;
      bool all_match = true;
      for (std::uint32_t t = 0; t < w * h; ++t)
        for (std::uint32_t c = 0; c < channels; ++c) {
          const std::byte* p = out.data() + (std::size_t{t} * channels + c) * channel_size;
          const float want[4] = {1.0f, 0.5f, 0.25f, 3.0f};
          double got = 0, expect = want[c];
          if (hal::format_is_uint(format)) {
            std::uint32_t u = 0;
            std::memcpy(&u, p, channel_size);  // little-endian: a 16-bit channel is the low half
            got = u;
            expect = static_cast<std::uint32_t>(want[c]);
          } else if (channel_size == 1) {
            got = static_cast<double>(std::to_integer<int>(*p)) / 255.0;
            expect = std::min(1.0, expect);
          } else if (channel_size == 2) {
            std::uint16_t half;
            std::memcpy(&half, p, 2);
            // Exact halves of the test values: 1.0, 0.5, 0.25, 3.0.
            const std::uint16_t halves[4] = {0x3c00, 0x3800, 0x3400, 0x4200};
            got = half == halves[c] ? expect : -1;
          } else {
            float f;
            std::memcpy(&f, p, 4);
            got = f;
          }
          if (std::abs(got - expect) > 1.0 / 255.0) all_match = false;
        }
      CHECK(all_match);
      for (auto buffer : {src, dst}) device.destroy(buffer);
      for (auto image : {a, b}) device.destroy(image);
    }
  });
}
