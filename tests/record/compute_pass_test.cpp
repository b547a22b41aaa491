// add_compute_pass: the shader's reflection decides read/write, and every name is checked against
// the shader when the pass is declared; PipelineCache checks the generated uniform struct. Runs without a GPU (nothing
// is recorded).
#include <doctest/doctest.h>

#include <string>

#include "asvgf/compute_pass.hpp"
#include "checked_record.hpp"
#include "hal/error.hpp"
#include "shaders/accumulate.hpp"
#include "shaders/atrous.history.hpp"
#include "shaders/atrous.plain.hpp"
#include "shaders/pack_surface.hpp"
#include "shaders/variance.plain.hpp"
#include "test_shaders.hpp"

using namespace asvgf;

namespace {

// The BindingMismatch message of declaring `bindings` for kImageShader, or "" when it succeeds.
std::string declare(std::vector<passes::Binding> bindings, std::size_t uniform_bytes = 16) {
  graph::RenderGraph g;
  const auto src = g.add_image("src", 8, 8, hal::Format::RGBA16F, graph::Lifetime::Persistent);
  const auto dst = g.add_image("dst", 8, 8, hal::Format::RGBA16F);
  for (auto& b : bindings) b.resource = b.name == "dst_image" ? dst : src;
  try {
    passes::add_compute_pass(g, "filter", record_test::kImageShader, {}, std::move(bindings),
                             std::vector<std::byte>(uniform_bytes), {8, 8, 1});
  } catch (const hal::Error& e) {
    CHECK(e.kind() == hal::ErrorKind::BindingMismatch);
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("add_compute_pass declares each binding with the access the shader reflects") {
  graph::RenderGraph g;
  const auto data = g.add_buffer("data", 64);
  const auto src = g.add_buffer("src", 64);
  const auto dst = g.add_buffer("dst", 64);
  passes::add_compute_pass(g, "copy", record_test::kCopyShader, {}, {{"src", src}, {"dst", dst}}, {}, {64, 1, 1});
  passes::add_compute_pass(g, "in_place", record_test::kInPlaceShader, {}, {{"data", data}}, {}, {64, 1, 1});
  REQUIRE(g.passes().size() == 2);
  const auto& copy = g.passes()[0].accesses;
  REQUIRE(copy.size() == 2);
  CHECK(copy[0].use == graph::Use::ShaderRead);
  CHECK(copy[1].use == graph::Use::ShaderWrite);
  REQUIRE(g.passes()[1].accesses.size() == 1);
  CHECK(g.passes()[1].accesses[0].use == graph::Use::ShaderReadWrite);
}

TEST_CASE("add_compute_pass rejects bindings that do not match the shader, naming pass, shader and binding") {
  CHECK(declare({{"src_image"}, {"dst_image"}}) == "");
  SUBCASE("a name the shader lacks") {
    const std::string what = declare({{"src_image"}, {"dst_image"}, {"sorce"}});
    CHECK(what.find("'filter_image'") != std::string::npos);
    CHECK(what.find("pass 'filter'") != std::string::npos);
    CHECK(what.find("no binding 'sorce'") != std::string::npos);
  }
  SUBCASE("a shader binding left unbound") {
    CHECK(declare({{"src_image"}}).find("shader binding 'dst_image' is left unbound") != std::string::npos);
  }
  SUBCASE("the uniform block is not a binding") {
    CHECK(declare({{"src_image"}, {"dst_image"}, {"params"}}).find("no binding 'params'") != std::string::npos);
  }
  SUBCASE("a binding given twice") {
    CHECK(declare({{"src_image"}, {"dst_image"}, {"src_image"}}).find("'src_image' is given twice") !=
          std::string::npos);
  }
  SUBCASE("a history binding the shader writes") {
    CHECK(declare({{"src_image"}, {"dst_image", 0, true}}).find("history binding 'dst_image' is written") !=
          std::string::npos);
  }
  SUBCASE("uniforms of the wrong size") {
    CHECK(declare({{"src_image"}, {"dst_image"}}, 12).find("12 bytes of uniforms for the shader's block of 16") !=
          std::string::npos);
  }
}

TEST_CASE("PipelineCache takes a generated uniform struct for any variant with the same block, and refuses others") {
  CheckedRecord checked;
  passes::PipelineCache cache(checked.device);
  using namespace asvgf::shaders;
  CHECK_NOTHROW(cache.get<atrous_plain_uniforms::Params>(atrous_history));
  auto refusal = [&](auto uniforms, const hal::ShaderInfo& shader) -> std::string {
    try {
      cache.get<decltype(uniforms)>(shader);
    } catch (const hal::Error& e) {
      CHECK(e.kind() == hal::ErrorKind::BindingMismatch);
      CHECK(e.object() == shader.name);
      return e.what();
    }
    return "";
  };
  // Another size: named with both shaders.
  const std::string size = refusal(pack_surface_uniforms::Params{}, variance_plain);
  CHECK(size.find("24 bytes in the shader, 16 in the C++ struct generated from 'pack_surface'") != std::string::npos);
  // The same size, another member at the same place.
  const std::string member = refusal(pack_surface_uniforms::Params{}, accumulate);
  CHECK(member.find("member 2 is 'history_valid' in the shader, 'depth_gradient_given'") != std::string::npos);
}
