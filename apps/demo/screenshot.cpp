#include "screenshot.hpp"

#include <cstdio>
#include <vector>

#include "io/image_io.hpp"

namespace asvgf::demo {

void save_png(hal::Device& device, hal::ImageHandle image, std::uint32_t width, std::uint32_t height,
              const std::filesystem::path& path) {
  std::vector<std::uint8_t> rgba(std::size_t(width) * height * 4);
  device.read_image(image, std::as_writable_bytes(std::span(rgba)));
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  render::write_png(path, width, height, rgba);
}

std::filesystem::path screenshot_name(const std::filesystem::path& dir, const std::string& method,
                                      const std::string& view, int frame) {
  char base[128];
  std::snprintf(base, sizeof base, "asvgf-demo_%s_%s_%05d", method.c_str(), view.c_str(), frame);
  std::filesystem::path path = dir / (std::string(base) + ".png");
  for (int n = 2; std::filesystem::exists(path); ++n) path = dir / (std::string(base) + "_" + std::to_string(n) + ".png");
  return path;
}

}  // namespace asvgf::demo
