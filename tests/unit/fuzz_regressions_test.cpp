// Inputs the fuzzers (tools/fuzz.sh) flagged, kept as regressions: each must load or fail with a
// clean exception through the same loader, in the normal build too (the sanitizer build that found
// them is tools/fuzz.sh's). tests/data/fuzz_regressions/<target>/ holds them; add one per finding.
#include <doctest/doctest.h>

#include <exception>
#include <filesystem>

#include "scene/mesh_import.hpp"
#include "scene/scene_file.hpp"

namespace fs = std::filesystem;

TEST_CASE("every fuzz regression input loads or fails with a clean error") {
  const fs::path root = fs::path(__FILE__).parent_path().parent_path() / "data" / "fuzz_regressions";
  int inputs = 0;
  for (const auto& kind : fs::directory_iterator(root)) {
    for (const auto& input : fs::directory_iterator(kind.path())) {
      CAPTURE(input.path().string());
      const std::string target = kind.path().filename().string();
      bool clean = true;
      try {
        using namespace asvgf::scene;
        if (target == "image")
          (void)detail::load_image(input.path(), "regression");
        else if (target == "obj")
          (void)detail::import_obj(input.path(), "regression");
        else if (target == "gltf")
          (void)detail::import_gltf(input.path(), "regression");
        else if (target == "scene_json")
          (void)load_scene_file(input.path());
        else
          FAIL("unknown fuzz target folder " << target);
      } catch (const std::exception& e) {
        clean = std::string(e.what()).find("regression") != std::string::npos || target == "scene_json";
        MESSAGE(std::string(e.what()));
      }
      CHECK(clean);
      ++inputs;
    }
  }
  CHECK(inputs >= 2);
}

TEST_CASE("a PNG whose chunk claims more bytes than the file holds is refused before decoding") {
  // stb_image asked for 2 GiB on this 76-byte file (tools/fuzz.sh found it): its last chunk claims 1.1 GB.
  const fs::path input = fs::path(__FILE__).parent_path().parent_path() / "data" / "fuzz_regressions" / "image" /
                         "png_chunk_claims_2gib.png";
  CHECK_THROWS_WITH_AS(asvgf::scene::detail::load_image(input, "regression"),
                       doctest::Contains("PNG chunk at byte 64 claims 1162757294 bytes but the file has 0 left"),
                       asvgf::scene::SceneError);
}

TEST_CASE("a JPEG Huffman table with more than 256 codes is refused before stb_image overruns its tables") {
  // stb_image 2.27 wrote past its 257-entry Huffman tables on this 47-byte file (tools/fuzz.sh, UBSan):
  // its DHT segment's 16 counts are 0x8b each, 2224 codes.
  const fs::path input = fs::path(__FILE__).parent_path().parent_path() / "data" / "fuzz_regressions" / "image" /
                         "jpeg_huffman_table_over_256_codes.jpg";
  CHECK_THROWS_WITH_AS(asvgf::scene::detail::load_image(input, "regression"),
                       doctest::Contains("JPEG Huffman table at byte 6 has 2224 codes (at most 256)"),
                       asvgf::scene::SceneError);
  // The same overrun behind 0xFF fill bytes before the start-of-image marker, which stb_image skips.
  CHECK_THROWS_WITH_AS(asvgf::scene::detail::load_image(input.parent_path() / "jpeg_fill_bytes_before_soi_huffman_overrun.jpg",
                                                        "regression"),
                       doctest::Contains("JPEG Huffman table at byte 115 has 964 codes (at most 256)"),
                       asvgf::scene::SceneError);
}

TEST_CASE("a JPEG scan that uses a Huffman table no DHT segment defined is refused before stb_image decodes it") {
  // stb_image 2.27 decoded this progressive file's first DC scan with DC table 3, never defined:
  // uninitialised memory, an index of -11198258 into a 257-entry table (tools/fuzz.sh, UBSan).
  const fs::path input = fs::path(__FILE__).parent_path().parent_path() / "data" / "fuzz_regressions" / "image" /
                         "jpeg_scan_uses_undefined_huffman_table.jpg";
  CHECK_THROWS_WITH_AS(asvgf::scene::detail::load_image(input, "regression"),
                       doctest::Contains("JPEG scan at byte 356 uses DC Huffman table 3, which no DHT segment before it defines"),
                       asvgf::scene::SceneError);
}

TEST_CASE("glTF images go through the same checks: an embedded JPEG with an overlong Huffman table is refused") {
  // tinygltf would hand this image to Debian's libstb unchecked; import_gltf decodes through decode_image.
  const fs::path input = fs::path(__FILE__).parent_path().parent_path() / "data" / "fuzz_regressions" / "gltf" /
                         "embedded_jpeg_huffman_table_over_256_codes.gltf";
  CHECK_THROWS_WITH_AS(asvgf::scene::detail::import_gltf(input, "regression"),
                       doctest::Contains("image 0: JPEG Huffman table at byte 6 has 2224 codes (at most 256)"),
                       asvgf::scene::SceneError);
}
