// Textures through scene::detail::load_image: JPEG files of every kind stb_image reads (baseline,
// progressive, with restart markers) pass the Huffman-table check that guards stb_image 2.27 and
// decode to their pixels. The files are cjpeg (libjpeg-turbo) encodings of a 16x16 pattern whose
// red channel is 16*x, green 16*y and blue 128 (cjpeg -quality 95 -sample 1x1).
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "renderer/scene/mesh_import.hpp"

namespace fs = std::filesystem;

TEST_CASE("JPEG textures (baseline, progressive, restart markers) load with their pixels") {
  const fs::path dir = fs::path(__FILE__).parent_path().parent_path() / "data" / "images";
  for (const std::string name : {"pattern_baseline.jpg", "pattern_progressive.jpg", "pattern_restart.jpg"}) {
    CAPTURE(name);
    const auto tex = asvgf::scene::detail::load_image(dir / name, "test");
    REQUIRE(tex.width == 16);
    REQUIRE(tex.height == 16);
    int worst = 0;
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 16; ++x) {
        const auto* p = &tex.rgba8[(static_cast<std::size_t>(y) * 16 + x) * 4];
        worst = std::max({worst, std::abs(p[0] - 16 * x), std::abs(p[1] - 16 * y)});
        CHECK(p[3] == 255);
      }
    MESSAGE(name << ": worst red/green error " << worst << " of 255");
    CHECK(worst <= 6);  // quality 95, no chroma subsampling, a smooth pattern
  }
}

TEST_CASE("a glTF texture decodes through the same loader: the example quad's checker reaches RGBA8 intact") {
  const fs::path dir = fs::path(__FILE__).parent_path().parent_path() / "data" / "scenes";
  const auto direct = asvgf::scene::detail::load_image(dir / "checker.png", "test");
  for (const char* file : {"quad.gltf", "quad.glb"}) {
    CAPTURE(file);
    const auto mesh = asvgf::scene::detail::import_gltf(dir / file, "test");
    REQUIRE(mesh.textures.size() == 1);
    CHECK(mesh.textures[0].width == direct.width);
    CHECK(mesh.textures[0].height == direct.height);
    CHECK(mesh.textures[0].rgba8 == direct.rgba8);
  }
}
