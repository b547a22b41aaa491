// The package consumer: opens a Vulkan device through the installed asvgf::hal_vulkan with the
// validation layer (synchronization validation on), uploads a buffer, copies half of it into a
// second one on the GPU and reads it back. Exit 0 only when the bytes match and the layer said
// nothing.
#include <hal/hal.hpp>
#include <hal_vulkan/vulkan.hpp>

#include <cstdio>
#include <cstring>
#include <exception>
#include <numeric>
#include <span>
#include <string>
#include <vector>

int main() {
  try {
    std::vector<std::string> messages;
    hal::vulkan::DeviceOptions options;
    options.validation = true;
    options.on_validation_message = [&messages](const std::string& m) { messages.push_back(m); };
    auto device = hal::vulkan::create_device(options);

    std::vector<std::uint32_t> words(1024);
    std::iota(words.begin(), words.end(), 7u);
    const std::uint64_t bytes = words.size() * sizeof(std::uint32_t);
    const auto usage = hal::BufferUsage::Storage | hal::BufferUsage::CopySrc | hal::BufferUsage::CopyDst;
    const hal::BufferHandle src = device->create_buffer({"consumer src", bytes, usage});
    const hal::BufferHandle dst = device->create_buffer({"consumer dst", bytes, usage});
    device->upload_buffer(src, 0, std::as_bytes(std::span(words)));
    device->upload_buffer(dst, 0, std::as_bytes(std::span(words)));

    auto commands = device->create_command_list("consumer copy");
    commands->barrier({{src, hal::State::CopyDst, hal::State::CopySrc}});
    commands->copy_buffer({src, dst, 0, bytes / 2, bytes / 2});
    commands->barrier({{dst, hal::State::CopyDst, hal::State::CopySrc}});
    device->submit(*commands);
    device->wait();

    std::vector<std::uint32_t> out(words.size());
    device->read_buffer(dst, 0, std::as_writable_bytes(std::span(out)));
    std::vector<std::uint32_t> expected = words;
    std::memcpy(expected.data() + words.size() / 2, words.data(), bytes / 2);
    commands.reset();
    device->destroy(src);
    device->destroy(dst);
    device.reset();

    if (out != expected) {
      std::fprintf(stderr, "asvgf_consumer: the copied buffer differs from what was uploaded\n");
      return 1;
    }
    for (const auto& m : messages) std::fprintf(stderr, "asvgf_consumer: validation: %s\n", m.c_str());
    if (!messages.empty()) return 1;
    std::printf("asvgf_consumer: %llu bytes copied and read back on %s through the installed package\n",
                static_cast<unsigned long long>(bytes / 2), options.adapter.empty() ? "the default adapter" : options.adapter.c_str());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "asvgf_consumer: %s\n", e.what());
    return 1;
  }
}
