// A test-only HAL backend that runs the shader tool's WGSL in Dawn: every call is forwarded to a
// Node process (tests/wgsl/webgpu_server.mjs, npm `webgpu` pinned in tools/package.json) over its
// stdin/stdout, with the protocol that file describes. It exists so that the tests written against
// the HAL (denoiser passes against their CPU references, frames against Vulkan) run the WGSL too.
//
// No acceleration structures (the frame picks its software-BVH variants) and no timestamps. Barriers
// are not forwarded: WebGPU orders the commands of a queue itself.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <utility>

#include "hal/device.hpp"

namespace hal::dawn_node {

struct DeviceOptions {
  std::string node;          // the node executable
  std::string server;        // webgpu_server.mjs
  std::string node_modules;  // where npm installed `webgpu`
  std::string shader_dir;    // where the shader tool wrote <shader>[.<variant>].wgsl
  // Dawn's validation errors; stderr when empty.
  std::function<void(const std::string&)> on_message;
};

// Starts the server and opens its adapter. Throws hal::Error(NoDevice) when Node or Dawn cannot start.
std::unique_ptr<hal::Device> create_device(const DeviceOptions& options);

#if defined(ASVGF_TEST_NODE)
// The options of this build: the test targets define where Node, the server, the npm packages and
// the shaders are.
inline DeviceOptions build_options(std::function<void(const std::string&)> on_message) {
  DeviceOptions options;
  options.node = ASVGF_TEST_NODE;
  options.server = ASVGF_TEST_WEBGPU_SERVER;
  options.node_modules = ASVGF_TEST_NODE_MODULES;
  options.shader_dir = ASVGF_TEST_SHADER_DIR;
  options.on_message = std::move(on_message);
  return options;
}
#endif

}  // namespace hal::dawn_node
