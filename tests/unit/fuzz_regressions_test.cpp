// Inputs the fuzzers (tools/fuzz.sh) flagged, kept as regressions: each must load or fail with a
// clean exception through the same loader, in the normal build too (the sanitizer build that found
// them is tools/fuzz.sh's). tests/data/fuzz_regressions/<target>/ holds them; add one per finding.
#include <doctest/doctest.h>

#include <exception>
#include <filesystem>

#include "renderer/scene/mesh_import.hpp"
#include "renderer/scene/scene_file.hpp"

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

// Each image finding, refused before stb_image (2.27, Debian 12) mishandles it, with the reason.
TEST_CASE("every image the fuzzers found stb_image mishandling is refused before decoding, naming why") {
  struct Finding {
    const char* file;
    const char* why;  // how stb_image failed on it
    const char* message;
  };
  const Finding findings[] = {
      {"png_chunk_claims_2gib.png", "76 bytes whose last chunk claims 1.1 GB: stb_image allocated 2 GiB",
       "PNG chunk at byte 64 claims 1162757294 bytes but the file has 0 left"},
      {"jpeg_huffman_table_over_256_codes.jpg", "DHT counts of 0x8b each: writes past the 257-entry tables",
       "JPEG Huffman table at byte 6 has 2224 codes (at most 256)"},
      {"jpeg_fill_bytes_before_soi_huffman_overrun.jpg", "the same behind 0xFF fill bytes before the start marker",
       "JPEG Huffman table at byte 115 has 964 codes (at most 256)"},
      {"jpeg_scan_uses_undefined_huffman_table.jpg", "a DC scan with table 3, never defined: uninitialised memory",
       "JPEG scan at byte 356 uses DC Huffman table 3, which no DHT segment before it defines"},
      {"tga_rle_claims_8224x8224_from_478_bytes.tga",
       "an RLE TGA padded with zeros to 67 M pixels: over 13 s to decode (fuzzer timeout)",
       "not a PNG or JPEG file"},
  };
  const fs::path dir = fs::path(__FILE__).parent_path().parent_path() / "data" / "fuzz_regressions" / "image";
  for (const Finding& f : findings) {
    CAPTURE(f.file);
    CAPTURE(f.why);
    CHECK_THROWS_WITH_AS(asvgf::scene::detail::load_image(dir / f.file, "regression"), doctest::Contains(f.message),
                         asvgf::scene::SceneError);
  }
}

TEST_CASE("glTF images go through the same checks: an embedded JPEG with an overlong Huffman table is refused") {
  // tinygltf would hand this image to Debian's libstb unchecked; import_gltf decodes through decode_image.
  const fs::path input = fs::path(__FILE__).parent_path().parent_path() / "data" / "fuzz_regressions" / "gltf" /
                         "embedded_jpeg_huffman_table_over_256_codes.gltf";
  CHECK_THROWS_WITH_AS(asvgf::scene::detail::import_gltf(input, "regression"),
                       doctest::Contains("image 0: JPEG Huffman table at byte 6 has 2224 codes (at most 256)"),
                       asvgf::scene::SceneError);
}
