// libFuzzer targets for the scene loader, one executable per input kind (ASVGF_FUZZ_TARGET):
// scene_json (a scene file, next to copies of tests/data/scenes so its references resolve), obj,
// gltf (.glb when the input starts with the binary magic, else .gltf) and image (through stb_image).
// A clean error is any std::exception (the tools turn it into a message and exit 1); a crash, a
// sanitizer report, a leak, a hang or an out-of-memory is a finding.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>

#include "renderer/scene/mesh_import.hpp"
#include "renderer/scene/scene_file.hpp"

namespace {

std::filesystem::path work_dir;

void write(const std::filesystem::path& path, const std::uint8_t* data, std::size_t size) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  work_dir = std::filesystem::temp_directory_path() / ("asvgf_fuzz_" + std::to_string(getpid()));
  std::filesystem::create_directories(work_dir);
  for (const auto& entry : std::filesystem::directory_iterator(ASVGF_FUZZ_DATA_DIR))
    std::filesystem::copy_file(entry.path(), work_dir / entry.path().filename(),
                               std::filesystem::copy_options::overwrite_existing);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace asvgf::scene;
  const std::string target = ASVGF_FUZZ_TARGET;
  try {
    if (target == "scene_json") {
      write(work_dir / "fuzz.json", data, size);
      (void)load_scene_file(work_dir / "fuzz.json");
    } else if (target == "obj") {
      write(work_dir / "fuzz.obj", data, size);
      (void)detail::import_obj(work_dir / "fuzz.obj", "fuzz");
    } else if (target == "gltf") {
      const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
      const auto file = work_dir / (binary ? "fuzz.glb" : "fuzz.gltf");
      write(file, data, size);
      (void)detail::import_gltf(file, "fuzz");
    } else if (target == "image") {
      write(work_dir / "fuzz.png", data, size);
      (void)detail::load_image(work_dir / "fuzz.png", "fuzz");
    }
  } catch (const std::exception&) {
    // A clean error: what the loader is for.
  }
  return 0;
}
