#include "cache_latency.hpp"

#include <algorithm>
#include <bit>
#include <random>
#include <span>
#include <string>

#include "hal/error.hpp"
#include "report/sequence_metrics.hpp"
#include "shaders/cache_latency.buffer.hpp"
#include "shaders/cache_latency.image.hpp"

namespace asvgf::cli {
namespace {

constexpr std::uint32_t kWordsPerElement = 32;     // 128 bytes: an element a cache line
constexpr std::uint32_t kMaxImageWidthShift = 12;  // the image variant's rows: up to 4096 r32ui texels

// One cycle through all elements (Sattolo's shuffle), in a random order so that no prefetcher or
// line-adjacency helps: word 32 e holds 32 * next(e), the other words of the line are unused.
std::vector<std::uint32_t> make_chain(std::uint32_t elements, std::uint32_t seed) {
  std::vector<std::uint32_t> next(elements);
  for (std::uint32_t e = 0; e < elements; ++e) next[e] = e;
  std::mt19937 rng(seed);
  for (std::uint32_t i = elements - 1; i > 0; --i) {
    std::uniform_int_distribution<std::uint32_t> pick(0, i - 1);
    std::swap(next[i], next[pick(rng)]);
  }
  std::vector<std::uint32_t> words(std::size_t{elements} * kWordsPerElement, 0u);
  for (std::uint32_t e = 0; e < elements; ++e) words[std::size_t{e} * kWordsPerElement] = next[e] * kWordsPerElement;
  return words;
}

// A host upload leaves the chain in CopyDst; the walks read it.
void make_readable(hal::Device& device, hal::Resource chain) {
  auto commands = device.create_command_list("cache latency chain");
  commands->barrier({chain, hal::State::CopyDst, hal::State::ShaderRead});
  device.submit(*commands);
  device.wait();
}

struct Walk {
  std::uint32_t steps, start_step, elements, groups;
  std::uint32_t width_shift = 0;  // the image variant's rows are 1 << width_shift texels
};

std::uint32_t host_walk(const std::vector<std::uint32_t>& words, const Walk& w, std::uint32_t group) {
  std::uint32_t word =
      kWordsPerElement * static_cast<std::uint32_t>((std::uint64_t{group} * w.start_step) % w.elements);
  for (std::uint32_t s = 0; s < w.steps; ++s) word = words[word];
  return word;
}

// Median ns a load of `repeats` timed walks; the walks' ends checked against the host's.
std::optional<double> time_walks(hal::Device& device, const hal::ShaderInfo& shader, hal::Resource chain,
                                 const std::vector<std::uint32_t>& words, const Walk& w, int repeats) {
  const auto usage = hal::BufferUsage::Storage | hal::BufferUsage::CopySrc;
  const hal::BufferHandle ends = device.create_buffer({"cache latency ends", std::uint64_t{w.groups} * 4, usage});
  const hal::TimerQueriesHandle timers =
      device.create_timer_queries({"cache latency walks", static_cast<std::uint32_t>(repeats)});
  const hal::PipelineHandle pipeline = device.create_pipeline({"cache latency", &shader});
  const hal::BindingSetHandle set =
      device.create_binding_set({"cache latency", pipeline, {{"chain", chain}, {"ends", ends}}});
  shaders::cache_latency_buffer_uniforms::Params params{};
  params.steps = w.steps;
  params.start_step = w.start_step;
  params.width_shift = w.width_shift;
  params.elements = w.elements;
  auto commands = device.create_command_list("cache latency");
  commands->barrier({ends, hal::State::Undefined, hal::State::ShaderWrite});
  for (int r = 0; r < repeats; ++r) {
    if (r > 0) commands->barrier({ends, hal::State::ShaderWrite, hal::State::ShaderWrite});
    commands->begin_timer(timers, static_cast<std::uint32_t>(r));
    commands->dispatch({pipeline, set, std::as_bytes(std::span(&params, 1)), w.groups, 1, 1});
    commands->end_timer(timers, static_cast<std::uint32_t>(r));
  }
  commands->barrier({ends, hal::State::ShaderWrite, hal::State::CopySrc});
  device.submit(*commands);
  device.wait();
  std::vector<double> ns;
  for (const auto& t : device.read_timers(timers))
    if (t && *t > 0.0) ns.push_back(*t * 1e6 / w.steps);
  std::vector<std::uint32_t> got(w.groups);
  device.read_buffer(ends, 0, std::as_writable_bytes(std::span(got)));
  commands.reset();
  device.destroy(set);
  device.destroy(pipeline);
  device.destroy(timers);
  device.destroy(ends);
  for (std::uint32_t g = 0; g < std::min(w.groups, 2u); ++g) {
    const std::uint32_t expected = host_walk(words, w, g);
    if (got[g] != expected)
      throw hal::Error(hal::ErrorKind::Backend, shader.name,
                       "cache latency probe: workgroup " + std::to_string(g) + "'s walk ended at word " +
                           std::to_string(got[g]) + ", the host's at " + std::to_string(expected));
  }
  if (ns.empty()) return std::nullopt;
  return report::median(ns);
}

}  // namespace

std::vector<CacheLatency> measure_cache_latency(hal::Device& device) {
  std::vector<CacheLatency> rows;
  if (!device.capabilities().timestamps) return rows;
  const bool cpu = device.adapter().type == hal::DeviceType::Cpu;
  // Fine steps where L1/shared-memory splits lie (tens to hundreds of KB), then L2 and beyond.
  std::vector<std::uint64_t> kib = {8,   16,  24,  32,  48,  64,   96,   128,   160,  192,
                                    224, 256, 320, 384, 512, 1024, 4096, 16384, 65536};
  if (cpu) kib = {8, 64, 512, 4096};  // a CPU device's walk is slow and its caches are not the GPU's
  // Every workgroup walks the same chain from its own start: enough of them to keep a GPU's clocks
  // up, each SM's cache shared by the workgroups it holds (which walk the same working set).
  const std::uint32_t groups = cpu ? 2 : 264, steps = cpu ? 4096 : 32768;
  for (const std::uint64_t k : kib) {
    const std::uint64_t bytes = k << 10;
    if (bytes > device.capabilities().max_storage_buffer_range) break;
    const Walk w{steps, 7919, static_cast<std::uint32_t>(bytes / (4 * kWordsPerElement)), groups};
    const std::vector<std::uint32_t> words = make_chain(w.elements, 1u);
    CacheLatency row;
    row.working_set = bytes;
    {
      const hal::BufferHandle chain =
          device.create_buffer({"cache latency chain", bytes, hal::BufferUsage::Storage | hal::BufferUsage::CopyDst});
      device.upload_buffer(chain, 0, std::as_bytes(std::span(words)));
      make_readable(device, chain);
      row.buffer_ns = time_walks(device, shaders::cache_latency_buffer, chain, words, w, 5);
      device.destroy(chain);
    }
    Walk wi = w;
    wi.width_shift = std::min<std::uint32_t>(kMaxImageWidthShift, std::bit_width(words.size()) - 1);
    const std::uint32_t width = 1u << wi.width_shift;
    const std::uint32_t height = static_cast<std::uint32_t>((words.size() + width - 1) / width);
    if (height <= device.capabilities().max_image_dimension) {
      const hal::ImageHandle chain = device.create_image({"cache latency chain", width, height, hal::Format::R32Uint,
                                                          hal::ImageUsage::Sampled | hal::ImageUsage::CopyDst});
      std::vector<std::uint32_t> texels = words;
      texels.resize(std::size_t{width} * height, 0u);  // the last row's tail: never reached
      device.upload_image(chain, std::as_bytes(std::span(texels)));
      make_readable(device, chain);
      row.image_ns = time_walks(device, shaders::cache_latency_image, chain, words, wi, 5);
      device.destroy(chain);
    }
    rows.push_back(row);
  }
  return rows;
}

}  // namespace asvgf::cli
