// The package consumer, written as a renderer integrating the denoiser would be: it links only the
// installed asvgf::denoiser and asvgf::hal_vulkan, opens a Vulkan device with the validation layer
// (synchronization validation on), fills its own G-buffer images (a plane facing the camera, noisy
// radiance around 0.5, albedo 1, no motion) and denoises 8 frames with SVGF. Exit 0 only when the
// output keeps the mean within 0.01 of the noise's expectation (0.5), has at most a quarter of the input's standard
// deviation, holds no NaN or Inf, and the layer said nothing.
#include <asvgf/denoiser.hpp>
// Every other public header, so that each installed one compiles from the installed tree alone.
#include <asvgf/compute_pass.hpp>
#include <asvgf/denoiser_graph.hpp>
#include <asvgf/graph_runtime.hpp>
#include <asvgf/pass_traffic.hpp>
#include <hal/hal.hpp>
#include <hal_vulkan/vulkan.hpp>

#include <cmath>
#include <cstdio>
#include <exception>
#include <random>
#include <span>
#include <string>
#include <vector>

namespace {

constexpr std::uint32_t kSize = 48;

struct Stats {
  double mean = 0, stddev = 0;
  bool finite = true;
};
Stats stats(const std::vector<float>& rgba) {
  Stats s;
  const double n = static_cast<double>(rgba.size() / 4);
  for (std::size_t i = 0; i < rgba.size(); i += 4) {
    s.finite = s.finite && std::isfinite(rgba[i]);
    s.mean += rgba[i] / n;
  }
  for (std::size_t i = 0; i < rgba.size(); i += 4) s.stddev += (rgba[i] - s.mean) * (rgba[i] - s.mean) / n;
  s.stddev = std::sqrt(s.stddev);
  return s;
}

}  // namespace

int main() {
  try {
    std::vector<std::string> messages;
    hal::vulkan::DeviceOptions options;
    options.validation = true;
    options.on_validation_message = [&messages](const std::string& m) { messages.push_back(m); };
    auto device = hal::vulkan::create_device(options);

    // The renderer's buffers: RGBA32F, uploaded from the host (a renderer writes them on the GPU).
    const auto usage =
        hal::ImageUsage::Sampled | hal::ImageUsage::Storage | hal::ImageUsage::CopySrc | hal::ImageUsage::CopyDst;
    auto image = [&](const char* name) {
      return device->create_image({name, kSize, kSize, hal::Format::RGBA32F, usage});
    };
    const hal::ImageHandle illumination = image("illumination"), albedo = image("albedo"), normal = image("normal"),
                           depth = image("depth"), motion = image("motion"), radiance = image("radiance");
    auto fill = [&](hal::ImageHandle target, float r, float g, float b) {
      std::vector<float> texels(kSize * kSize * 4);
      for (std::size_t i = 0; i < texels.size(); i += 4) texels[i] = r, texels[i + 1] = g, texels[i + 2] = b;
      device->upload_image(target, std::as_bytes(std::span(texels)));
    };
    fill(albedo, 1, 1, 1);
    fill(normal, 0, 0, -1);  // facing the camera
    fill(depth, 2, 0, 0);    // linear depth 2
    fill(motion, 0, 0, 0);   // nothing moves

    asvgf::Denoiser denoiser(*device, {.width = kSize, .height = kSize, .method = asvgf::DenoiseMethod::Svgf});
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> noise(0.0f, 1.0f);
    std::vector<float> noisy(kSize * kSize * 4), out(kSize * kSize * 4);
    for (int frame = 0; frame < 8; ++frame) {
      for (std::size_t i = 0; i < noisy.size(); i += 4) noisy[i] = noisy[i + 1] = noisy[i + 2] = noise(rng);
      device->upload_image(illumination, std::as_bytes(std::span(noisy)));
      const auto in = hal::State::CopyDst;                         // where upload_image left them (first frame) ...
      const auto read = frame == 0 ? in : hal::State::ShaderRead;  // ... and where the denoiser did
      denoiser.denoise(
          {.illumination = {illumination, hal::Format::RGBA32F, in},
           .albedo = {albedo, hal::Format::RGBA32F, read},
           .normal = {normal, hal::Format::RGBA32F, read},
           .depth = {depth, hal::Format::RGBA32F, read},
           .motion = {motion, hal::Format::RGBA32F, read}},
          {.radiance = {radiance, hal::Format::RGBA32F, frame == 0 ? hal::State::Undefined : hal::State::CopySrc},
           .final_state = hal::State::CopySrc});
      device->read_image(radiance, std::as_writable_bytes(std::span(out)));
    }
    const Stats before = stats(noisy), after = stats(out);
    for (auto h : {illumination, albedo, normal, depth, motion, radiance}) device->destroy(h);
    std::printf("asvgf_consumer: noisy mean %.4f sd %.4f, denoised mean %.4f sd %.4f\n", before.mean, before.stddev,
                after.mean, after.stddev);
    for (const auto& m : messages) std::fprintf(stderr, "asvgf_consumer: validation: %s\n", m.c_str());
    if (!messages.empty()) return 1;
    if (!after.finite || std::abs(after.mean - 0.5) > 0.01 || after.stddev > before.stddev / 4) {
      std::fprintf(stderr, "asvgf_consumer: the denoised image is not the smooth plane expected\n");
      return 1;
    }
    std::printf("asvgf_consumer: denoised %ux%u through the installed package, validation silent\n", kSize, kSize);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "asvgf_consumer: %s\n", e.what());
    return 1;
  }
}
