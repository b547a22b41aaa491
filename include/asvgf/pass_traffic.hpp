// asvgf/pass_traffic.hpp: the bytes each pass of a compiled frame must read and write, from the
// graph's declarations: every image it declares (width x height x texel size of its format) and
// every buffer of known size, each counted once however often the shader touches it. That is the
// compulsory traffic, which bounds a pass's time from below at a memory bandwidth.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "asvgf/compiled_frame.hpp"

namespace asvgf::graph {

// One declared resource of a pass: its bytes (0: size unknown) and how the pass uses it.
struct ResourceTraffic {
  std::string name;
  std::uint64_t bytes = 0;
  bool read = false, written = false;
  bool history = false;  // read as last frame's version
};

struct PassTraffic {
  std::string pass;
  std::uint64_t read_bytes = 0, written_bytes = 0;
  // The pass also reads resources of unknown size (imported scene buffers: a traversal's random
  // reads), so its bytes are a lower bound and no floor follows from them.
  bool uncounted_reads = false;
  std::vector<ResourceTraffic> resources;  // what the bytes are, in declaration order
};

// Per executed pass, in execution order.
std::vector<PassTraffic> pass_traffic(const CompiledFrame& frame);

}  // namespace asvgf::graph
