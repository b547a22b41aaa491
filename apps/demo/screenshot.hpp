// demo/screenshot.hpp: saving what the window shows as a PNG.
#pragma once

#include <filesystem>
#include <string>

#include "hal/device.hpp"

namespace asvgf::demo {

// Reads `image` (RGBA8, in State::CopySrc, left there) back and writes it as an 8-bit PNG.
void save_png(hal::Device& device, hal::ImageHandle image, std::uint32_t width, std::uint32_t height,
              const std::filesystem::path& path);

// A fresh name in `dir`: asvgf-demo_<method>_<view>_<frame>.png, with a counter if taken.
std::filesystem::path screenshot_name(const std::filesystem::path& dir, const std::string& method,
                                      const std::string& view, int frame);

}  // namespace asvgf::demo
