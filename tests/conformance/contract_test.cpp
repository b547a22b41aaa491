// The HAL contract, one rule at a time, on every backend behind the validation layer
// (hal/validate.hpp): each rule's violating call must throw hal::Error of the rule's kind naming
// the rule's object, and the nearest valid call must go through to the backend and succeed.
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "backends.hpp"
#include "shaders/hal_test_image.hpp"
#include "shaders/hal_test_ray_query.rayquery.hpp"
#include "shaders/hal_test_scale.hpp"

using namespace conformance;
using hal::BufferUsage;
using hal::ErrorKind;
using hal::Format;
using hal::ImageUsage;
using hal::State;

namespace {

constexpr auto kAnyBuffer = BufferUsage::Storage | BufferUsage::CopySrc | BufferUsage::CopyDst;
constexpr auto kAnyImage = ImageUsage::Sampled | ImageUsage::Storage | ImageUsage::CopySrc | ImageUsage::CopyDst;

// Objects a rule starts from, made fresh for each rule on the backend's device.
struct Setup {
  hal::Device& device;
  const hal::ShaderInfo& scale = asvgf::shaders::hal_test_scale;  // uniform block, src, dst buffers
  const hal::ShaderInfo& image = asvgf::shaders::hal_test_image;  // texture2D src, rgba32f storage dst
  std::unique_ptr<hal::CommandList> cmd = device.create_command_list("rule list");
  std::vector<std::byte> scale_uniforms = std::vector<std::byte>(scale.uniform_block_size);

  hal::BufferHandle buffer(const std::string& name, std::uint64_t size = 256, BufferUsage usage = kAnyBuffer) {
    return device.create_buffer({name, size, usage});
  }
  hal::ImageHandle image_of(const std::string& name, Format format = Format::RGBA32F, ImageUsage usage = kAnyImage,
                            std::uint32_t side = 4) {
    return device.create_image({name, side, side, format, usage});
  }
  hal::PipelineHandle scale_pipeline(const std::string& name = "scale pipeline") {
    return device.create_pipeline({name, &scale});
  }
  hal::BindingSetHandle scale_set(const std::string& name, hal::PipelineHandle pipeline) {
    return device.create_binding_set(
        {name, pipeline, {{"src", buffer(name + " src")}, {"dst", buffer(name + " dst")}}});
  }
  hal::DispatchDesc scale_dispatch(hal::PipelineHandle pipeline, hal::BindingSetHandle set) {
    return {pipeline, set, scale_uniforms, 1, 1, 1};
  }
  bool accels() const { return device.capabilities().acceleration_structures; }
  hal::AccelHandle blas(const std::string& name, bool allow_update = false) {
    const auto boxes = buffer(name + " boxes", 24, BufferUsage::AccelBuildInput);
    return device.create_blas(hal::BlasDesc::of_boxes(name, boxes, 1, allow_update));
  }
  void submit_and_wait() {
    device.submit(*cmd);
    device.wait();
  }
};

struct Rule {
  const char* rule;                   // the contract sentence, as the HAL headers state it
  ErrorKind kind;                     // what the violation throws
  std::string object;                 // the debug name the error must carry
  std::function<void(Setup&)> valid;  // the nearest valid use (may be empty)
  std::function<void(Setup&)> breaks;
  enum class Needs { Nothing, Accels, RayQuery } needs = Needs::Nothing;  // rules the device can't try are skipped
};

constexpr auto kAccels = Rule::Needs::Accels;

std::vector<Rule> rules() {
  std::vector<Rule> r;
  // ---- creation (hal/device.hpp, hal/types.hpp) ----
  r.push_back({"a buffer has a non-zero size", ErrorKind::InvalidDescriptor, "empty buffer",
               [](Setup& s) { s.buffer("one byte", 1); }, [](Setup& s) { s.buffer("empty buffer", 0); }});
  r.push_back({"a buffer size is not absurd", ErrorKind::InvalidDescriptor, "huge buffer", {}, [](Setup& s) {
                 s.buffer("huge buffer", ~std::uint64_t{0});
               }});
  r.push_back({"a buffer has a usage", ErrorKind::InvalidDescriptor, "unusable buffer", {}, [](Setup& s) {
                 s.buffer("unusable buffer", 64, BufferUsage::None);
               }});
  r.push_back({"a buffer fits the device's largest buffer", ErrorKind::OutOfMemory, "too big buffer", {}, [](Setup& s) {
                 const std::uint64_t max = s.device.capabilities().max_buffer_size;
                 s.buffer("too big buffer", max ? max + 1 : std::uint64_t{1} << 47);
               }});
  r.push_back({"an image has no zero side", ErrorKind::InvalidDescriptor, "flat image",
               [](Setup& s) { s.image_of("thin image", Format::RGBA32F, kAnyImage, 1); },
               [](Setup& s) {
                 s.device.create_image({"flat image", 16, 0, Format::RGBA16F});
               }});
  r.push_back(
      {"an image side is within max_image_dimension", ErrorKind::InvalidDescriptor, "vast image", {}, [](Setup& s) {
         s.device.create_image({"vast image", 1u << 30, 4, Format::RGBA16F});
       }});
  r.push_back({"an image has a format", ErrorKind::InvalidDescriptor, "formatless", {}, [](Setup& s) {
                 s.device.create_image({"formatless", 4, 4, Format::Undefined});
               }});
  r.push_back({"an image format is one of hal::Format", ErrorKind::InvalidDescriptor, "alien format", {}, [](Setup& s) {
                 s.device.create_image({"alien format", 4, 4, static_cast<Format>(200)});
               }});
  r.push_back({"an image has a usage", ErrorKind::InvalidDescriptor, "unusable image", {}, [](Setup& s) {
                 s.image_of("unusable image", Format::RGBA32F, ImageUsage::None);
               }});
  r.push_back({"timer queries have at least one region", ErrorKind::InvalidDescriptor, "no regions",
               [](Setup& s) {
                 s.device.create_timer_queries({"one region", 1});
               },
               [](Setup& s) {
                 s.device.create_timer_queries({"no regions", 0});
               }});
  r.push_back({"a pipeline has a shader", ErrorKind::InvalidDescriptor, "shaderless",
               [](Setup& s) { s.scale_pipeline(); },
               [](Setup& s) {
                 s.device.create_pipeline({"shaderless", nullptr});
               }});
  // ---- binding sets (Device::create_binding_set) ----
  r.push_back({"every entry names a binding of the shader", ErrorKind::BindingMismatch, "typo set",
               [](Setup& s) { s.scale_set("good set", s.scale_pipeline()); },
               [](Setup& s) {
                 s.device.create_binding_set(
                     {"typo set", s.scale_pipeline(), {{"source", s.buffer("a")}, {"dst", s.buffer("b")}}});
               }});
  r.push_back({"the uniform block is bound implicitly, never by an entry",
               ErrorKind::BindingMismatch,
               "block set",
               {},
               [](Setup& s) {
                 s.device.create_binding_set({"block set", s.scale_pipeline(), {{"params", s.buffer("p")}}});
               }});
  r.push_back(
      {"an entry's resource kind matches the binding's kind", ErrorKind::BindingMismatch, "kind set", {}, [](Setup& s) {
         s.device.create_binding_set(
             {"kind set", s.scale_pipeline(), {{"src", s.image_of("an image")}, {"dst", s.buffer("b")}}});
       }});
  r.push_back({"a binding is given once", ErrorKind::BindingMismatch, "twice set", {}, [](Setup& s) {
                 const auto b = s.buffer("b");
                 s.device.create_binding_set({"twice set", s.scale_pipeline(), {{"src", b}, {"src", b}}});
               }});
  r.push_back({"a bound buffer has Storage usage", ErrorKind::InvalidUsage, "copy-only buffer", {}, [](Setup& s) {
                 const auto b = s.buffer("copy-only buffer", 256, BufferUsage::CopySrc);
                 s.device.create_binding_set({"set", s.scale_pipeline(), {{"src", b}}});
               }});
  r.push_back({"a sampled image has Sampled usage", ErrorKind::InvalidUsage, "unsampled image", {}, [](Setup& s) {
                 const auto pipe = s.device.create_pipeline({"image pipeline", &s.image});
                 const auto img = s.image_of("unsampled image", Format::RGBA32F, ImageUsage::Storage);
                 s.device.create_binding_set({"set", pipe, {{"src_image", img}}});
               }});
  r.push_back({"a storage image has Storage usage", ErrorKind::InvalidUsage, "read-only image", {}, [](Setup& s) {
                 const auto pipe = s.device.create_pipeline({"image pipeline", &s.image});
                 const auto img = s.image_of("read-only image", Format::RGBA32F, ImageUsage::Sampled);
                 s.device.create_binding_set({"set", pipe, {{"dst_image", img}}});
               }});
  r.push_back(
      {"a storage image has the format the shader declares", ErrorKind::BindingMismatch, "format set",
       [](Setup& s) {
         const auto pipe = s.device.create_pipeline({"image pipeline", &s.image});
         s.device.create_binding_set({"rgba32f set", pipe, {{"dst_image", s.image_of("rgba32f")}}});
       },
       [](Setup& s) {
         const auto pipe = s.device.create_pipeline({"image pipeline", &s.image});
         s.device.create_binding_set({"format set", pipe, {{"dst_image", s.image_of("rgba16f", Format::RGBA16F)}}});
       }});
  r.push_back({"an acceleration-structure binding takes a top-level structure",
               ErrorKind::BindingMismatch,
               "bottom set",
               {},
               [](Setup& s) {
                 const auto pipe = s.device.create_pipeline({"trace", &asvgf::shaders::hal_test_ray_query_rayquery});
                 s.device.create_binding_set({"bottom set", pipe, {{"scene", s.blas("a blas")}}});
               },
               Rule::Needs::RayQuery});
  // ---- dispatches (hal/command_list.hpp DispatchDesc) ----
  r.push_back({"a binding set fits any pipeline of the shader it was made for", ErrorKind::InvalidUsage, "scale set",
               [](Setup& s) {
                 const auto set = s.scale_set("scale set", s.scale_pipeline("first"));
                 s.cmd->dispatch(s.scale_dispatch(s.scale_pipeline("second"), set));
               },
               [](Setup& s) {
                 const auto set = s.scale_set("scale set", s.scale_pipeline());
                 const auto other = s.device.create_pipeline({"image pipeline", &s.image});
                 std::vector<std::byte> uniforms(s.image.uniform_block_size);
                 s.cmd->dispatch({other, set, uniforms, 1, 1, 1});
               }});
  r.push_back({"a dispatch leaves no binding unbound", ErrorKind::InvalidUsage, "partial set", {}, [](Setup& s) {
                 const auto pipe = s.scale_pipeline();
                 const auto set = s.device.create_binding_set({"partial set", pipe, {{"src", s.buffer("src")}}});
                 s.cmd->dispatch(s.scale_dispatch(pipe, set));
               }});
  r.push_back(
      {"a dispatch binds no destroyed resource", ErrorKind::InvalidHandle, "stale set", {}, [](Setup& s) {
         const auto pipe = s.scale_pipeline();
         const auto dst = s.buffer("gone");
         const auto set = s.device.create_binding_set({"stale set", pipe, {{"src", s.buffer("src")}, {"dst", dst}}});
         s.device.destroy(dst);
         s.cmd->dispatch(s.scale_dispatch(pipe, set));
       }});
  r.push_back(
      {"uniform bytes match the reflected block size", ErrorKind::InvalidUsage, "scale pipeline", {}, [](Setup& s) {
         const auto pipe = s.scale_pipeline();
         const std::vector<std::byte> two(2);
         s.cmd->dispatch({pipe, s.scale_set("set", pipe), two, 1, 1, 1});
       }});
  r.push_back({"a dispatch has at least one workgroup in each dimension",
               ErrorKind::InvalidUsage,
               "scale pipeline",
               {},
               [](Setup& s) {
                 const auto pipe = s.scale_pipeline();
                 auto d = s.scale_dispatch(pipe, s.scale_set("set", pipe));
                 d.groups_y = 0;
                 s.cmd->dispatch(d);
               }});
  // ---- barriers ----
  r.push_back({"a barrier moves between states of the resource's kind", ErrorKind::InvalidUsage, "a buffer",
               [](Setup& s) {
                 s.cmd->barrier({s.buffer("a buffer"), State::Undefined, State::ShaderWrite});
               },
               [](Setup& s) {
                 s.cmd->barrier({s.buffer("a buffer"), State::Undefined, State::Present});
               }});
  r.push_back(
      {"an image is never an acceleration-structure input", ErrorKind::InvalidUsage, "an image", {}, [](Setup& s) {
         s.cmd->barrier({s.image_of("an image"), State::Undefined, State::AccelBuildInput});
       }});
  r.push_back({"Undefined is only a before-state", ErrorKind::InvalidUsage, "an image", {}, [](Setup& s) {
                 s.cmd->barrier({s.image_of("an image"), State::ShaderRead, State::Undefined});
               }});
  r.push_back({"a barrier names an existing resource", ErrorKind::InvalidHandle, "buffer", {}, [](Setup& s) {
                 s.cmd->barrier({hal::BufferHandle{999999}, State::Undefined, State::ShaderRead});
               }});
  // ---- copies and clears ----
  r.push_back({"a copy source has CopySrc usage", ErrorKind::InvalidUsage, "storage only", {}, [](Setup& s) {
                 s.cmd->copy_buffer({s.buffer("storage only", 256, BufferUsage::Storage), s.buffer("dst"), 0, 0, 4});
               }});
  r.push_back({"a copy stays inside both buffers", ErrorKind::InvalidUsage, "short dst",
               [](Setup& s) {
                 s.cmd->copy_buffer({s.buffer("src"), s.buffer("dst", 16), 0, 0, 16});
               },
               [](Setup& s) {
                 s.cmd->copy_buffer({s.buffer("src"), s.buffer("short dst", 16), 0, 8, 16});
               }});
  r.push_back({"a copy moves at least one byte", ErrorKind::InvalidUsage, "src", {}, [](Setup& s) {
                 s.cmd->copy_buffer({s.buffer("src"), s.buffer("dst"), 0, 0, 0});
               }});
  r.push_back({"copy_image needs the same size and format", ErrorKind::InvalidUsage, "half dst", {}, [](Setup& s) {
                 s.cmd->copy_image(s.image_of("full src"), s.image_of("half dst", Format::RGBA16F));
               }});
  r.push_back(
      {"a buffer copied to an image holds the whole image", ErrorKind::InvalidUsage, "small staging", {}, [](Setup& s) {
         s.cmd->copy_buffer_to_image(s.buffer("small staging", 16), s.image_of("image"));
       }});
  r.push_back({"clear_buffer needs at least 4 bytes", ErrorKind::InvalidUsage, "tiny", {}, [](Setup& s) {
                 s.cmd->clear_buffer(s.buffer("tiny", 2), 0);
               }});
  r.push_back({"a cleared image has CopyDst usage", ErrorKind::InvalidUsage, "sampled only", {}, [](Setup& s) {
                 s.cmd->clear_image(s.image_of("sampled only", Format::RGBA32F, ImageUsage::Sampled), {});
               }});
  // ---- acceleration structures ----
  r.push_back({"BLAS inputs have AccelBuildInput usage",
               ErrorKind::InvalidUsage,
               "plain boxes",
               {},
               [](Setup& s) {
                 const auto boxes = s.buffer("plain boxes", 24, BufferUsage::Storage);
                 s.device.create_blas(hal::BlasDesc::of_boxes("blas", boxes, 1));
               },
               kAccels});
  r.push_back({"a BLAS has at least one primitive",
               ErrorKind::InvalidDescriptor,
               "empty blas",
               {},
               [](Setup& s) {
                 const auto boxes = s.buffer("boxes", 24, BufferUsage::AccelBuildInput);
                 s.device.create_blas(hal::BlasDesc::of_boxes("empty blas", boxes, 0));
               },
               kAccels});
  r.push_back({"build_blas builds a bottom-level structure",
               ErrorKind::InvalidUsage,
               "a tlas",
               {},
               [](Setup& s) {
                 s.cmd->build_blas(s.device.create_tlas({"a tlas", 1}), false);
               },
               kAccels});
  r.push_back({"an update needs allow_update",
               ErrorKind::InvalidUsage,
               "fixed blas",
               {},
               [](Setup& s) {
                 const auto b = s.blas("fixed blas");
                 s.cmd->build_blas(b, false);
                 s.cmd->build_blas(b, true);
               },
               kAccels});
  r.push_back({"an update needs an earlier build",
               ErrorKind::InvalidUsage,
               "unbuilt blas",
               {},
               [](Setup& s) { s.cmd->build_blas(s.blas("unbuilt blas", true), true); },
               kAccels});
  r.push_back({"a TLAS holds at most max_instances",
               ErrorKind::InvalidUsage,
               "one-slot tlas",
               {},
               [](Setup& s) {
                 const auto b = s.blas("blas");
                 const std::array<hal::TlasInstance, 2> two{hal::TlasInstance{b}, hal::TlasInstance{b}};
                 s.cmd->build_tlas(s.device.create_tlas({"one-slot tlas", 1}), two, false);
               },
               kAccels});
  r.push_back({"an instance refers to a bottom-level structure",
               ErrorKind::InvalidUsage,
               "outer tlas",
               {},
               [](Setup& s) {
                 const std::array<hal::TlasInstance, 1> inner{hal::TlasInstance{s.device.create_tlas({"inner", 1})}};
                 s.cmd->build_tlas(s.device.create_tlas({"outer tlas", 1}), inner, false);
               },
               kAccels});
  // ---- timers ----
  r.push_back({"a timer region is within the queries", ErrorKind::InvalidUsage, "two regions",
               [](Setup& s) {
                 s.cmd->begin_timer(s.device.create_timer_queries({"two regions", 2}), 1);
               },
               [](Setup& s) {
                 s.cmd->begin_timer(s.device.create_timer_queries({"two regions", 2}), 2);
               }});
  // ---- host transfers ----
  r.push_back({"upload_buffer needs CopyDst usage", ErrorKind::InvalidUsage, "gpu only", {}, [](Setup& s) {
                 const std::array<std::byte, 4> data{};
                 s.device.upload_buffer(s.buffer("gpu only", 64, BufferUsage::Storage), 0, data);
               }});
  r.push_back({"an upload stays inside the buffer", ErrorKind::InvalidUsage, "small",
               [](Setup& s) {
                 const std::array<std::byte, 4> data{};
                 s.device.upload_buffer(s.buffer("small", 8), 4, data);
               },
               [](Setup& s) {
                 const std::array<std::byte, 4> data{};
                 s.device.upload_buffer(s.buffer("small", 8), 6, data);
               }});
  r.push_back({"an image readback takes exactly the whole image", ErrorKind::InvalidUsage, "image", {}, [](Setup& s) {
                 std::vector<std::byte> out(10);
                 s.device.read_image(s.image_of("image"), out);
               }});
  // ---- handles ----
  r.push_back({"an object is destroyed once", ErrorKind::InvalidHandle, "short lived", {}, [](Setup& s) {
                 const auto b = s.buffer("short lived");
                 s.device.destroy(b);
                 s.device.destroy(b);
               }});
  r.push_back({"a destroyed object is not used", ErrorKind::InvalidHandle, "short lived", {}, [](Setup& s) {
                 const auto b = s.buffer("short lived");
                 s.device.destroy(b);
                 const std::array<std::byte, 4> data{};
                 s.device.upload_buffer(b, 0, data);
               }});
  // ---- command-list lifecycle ----
  r.push_back({"end_label closes a begin_label", ErrorKind::InvalidUsage, "rule list", {}, [](Setup& s) {
                 s.cmd->end_label();
               }});
  r.push_back({"no label is left open at submit", ErrorKind::InvalidUsage, "rule list",
               [](Setup& s) {
                 s.cmd->begin_label("closed");
                 s.cmd->end_label();
                 s.submit_and_wait();
               },
               [](Setup& s) {
                 s.cmd->begin_label("open");
                 s.device.submit(*s.cmd);
               }});
  r.push_back({"a submitted list is reset before it is recorded again", ErrorKind::InvalidUsage, "rule list",
               [](Setup& s) {
                 s.submit_and_wait();
                 s.cmd->reset();
                 s.cmd->begin_label("again");
                 s.cmd->end_label();
               },
               [](Setup& s) {
                 s.submit_and_wait();
                 s.cmd->begin_label("again");
               }});
  r.push_back({"a list is not reset before wait() returns", ErrorKind::InvalidUsage, "rule list", {}, [](Setup& s) {
                 s.device.submit(*s.cmd);
                 s.cmd->reset();
               }});
  r.push_back({"a list is not submitted again before wait() returns", ErrorKind::InvalidUsage, "rule list",
               [](Setup& s) {
                 s.submit_and_wait();
                 s.submit_and_wait();
               },
               [](Setup& s) {
                 s.device.submit(*s.cmd);
                 s.device.submit(*s.cmd);
               }});
  return r;
}

}  // namespace

TEST_CASE("conformance: every rule of the HAL contract throws its kind naming the object, on every backend") {
  for_every_backend([](hal::Device& device, bool) {
    int checked = 0;
    for (const Rule& rule : rules()) {
      const std::string rule_text = rule.rule;
      CAPTURE(rule_text);
      const auto& caps = device.capabilities();
      if (rule.needs == Rule::Needs::Accels && !caps.acceleration_structures) continue;
      if (rule.needs == Rule::Needs::RayQuery && !(caps.acceleration_structures && caps.ray_query)) continue;
      if (rule.valid) {
        Setup s{device};
        CHECK_NOTHROW(rule.valid(s));
        device.wait();
      }
      Setup s{device};
      try {
        rule.breaks(s);
        FAIL_CHECK("no error for a call that breaks the rule");
      } catch (const hal::Error& e) {
        CHECK_MESSAGE(e.kind() == rule.kind, e.what());
        CHECK_MESSAGE(e.object() == rule.object, e.what());
      }
      device.wait();  // a rule may leave its list submitted
      ++checked;
    }
    CHECK(checked >= 40);
  });
}

TEST_CASE("conformance: a list from another device is refused at submit") {
  REQUIRE(!backends().empty());
  TestDevice one(backends().front()), other(backends().front());
  auto foreign = other->create_command_list("foreign list");
  try {
    one->submit(*foreign);
    FAIL_CHECK("submitting another device's list should throw");
  } catch (const hal::Error& e) {
    CHECK(e.kind() == ErrorKind::InvalidUsage);
  }
}
