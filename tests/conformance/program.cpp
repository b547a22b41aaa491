#include "program.hpp"

#include "data.hpp"
#include "shaders/hal_test_scale.hpp"

namespace conformance {

std::vector<float> run_multi_dispatch_program(hal::Device& device, const std::vector<float>& input) {
  using hal::State;
  const hal::ShaderInfo& shader = asvgf::shaders::hal_test_scale;
  const auto count = static_cast<std::uint32_t>(input.size());
  const std::uint64_t bytes = std::uint64_t{count} * 4;
  const auto usage = hal::BufferUsage::Storage | hal::BufferUsage::CopySrc | hal::BufferUsage::CopyDst;
  const auto a = device.create_buffer({"program a", bytes, usage});
  const auto b = device.create_buffer({"program b", bytes, usage});
  const auto c = device.create_buffer({"program c", bytes, usage});
  const auto pipeline = device.create_pipeline({"program scale", &shader});
  const auto first = device.create_binding_set({"program a->b", pipeline, {{"src", a}, {"dst", b}}});
  const auto second = device.create_binding_set({"program c->a", pipeline, {{"src", c}, {"dst", a}}});
  const std::uint32_t groups = (count + shader.workgroup_size[0] - 1) / shader.workgroup_size[0];
  device.upload_buffer(a, 0, as_bytes(input));

  auto cmd = device.create_command_list("program");
  cmd->begin_label("first pass");
  cmd->barrier({a, State::CopyDst, State::ShaderRead});
  cmd->barrier({b, State::Undefined, State::ShaderWrite});
  Uniforms u1(shader);
  u1.set("count", count).set("scale", 2.0f).set("offset", 1.0f);
  cmd->dispatch({pipeline, first, u1.bytes(), groups, 1, 1});
  cmd->end_label();
  cmd->begin_label("copy");
  cmd->barrier({b, State::ShaderWrite, State::CopySrc});
  cmd->barrier({c, State::Undefined, State::CopyDst});
  cmd->copy_buffer({b, c, 0, 0, bytes});
  cmd->end_label();
  cmd->begin_label("second pass");
  cmd->barrier({c, State::CopyDst, State::ShaderRead});
  cmd->barrier({a, State::ShaderRead, State::ShaderWrite});  // a is overwritten after its read
  Uniforms u2(shader);
  u2.set("count", count).set("scale", 0.5f).set("offset", -3.0f);
  cmd->dispatch({pipeline, second, u2.bytes(), groups, 1, 1});
  cmd->barrier({a, State::ShaderWrite, State::CopySrc});
  cmd->end_label();
  device.submit(*cmd);
  device.wait();

  std::vector<float> out(count);
  device.read_buffer(a, 0, as_writable(out));
  device.destroy(first);
  device.destroy(second);
  device.destroy(pipeline);
  for (auto buffer : {a, b, c}) device.destroy(buffer);
  return out;
}

}  // namespace conformance
