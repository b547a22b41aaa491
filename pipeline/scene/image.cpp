// scene/image.cpp: albedo textures from image files through stb_image.
//
// libtinygltf.so links Debian's libstb.so, which exports the stb_image symbols; STB_IMAGE_STATIC
// keeps this implementation private to this file so the two never clash.
#include <cstring>

#include "scene/mesh_import.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wall"
#pragma GCC diagnostic ignored "-Wextra"
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wcast-align"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

namespace asvgf::scene::detail {

Texture load_image(const std::filesystem::path& file, const std::string& where) {
  int width = 0, height = 0, channels = 0;
  stbi_uc* pixels = stbi_load(file.string().c_str(), &width, &height, &channels, 4);
  if (pixels == nullptr) {
    const char* reason = stbi_failure_reason();
    throw SceneError(where + ": " + file.string() + ": cannot read image (" + (reason ? reason : "unknown error") + ")");
  }
  Texture tex;
  tex.name = file.string();
  tex.width = static_cast<std::uint32_t>(width);
  tex.height = static_cast<std::uint32_t>(height);
  tex.rgba8.resize(std::size_t{tex.width} * tex.height * 4);
  std::memcpy(tex.rgba8.data(), pixels, tex.rgba8.size());
  stbi_image_free(pixels);
  return tex;
}

}  // namespace asvgf::scene::detail
