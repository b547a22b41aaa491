// cpu_oracle/image.hpp: a plain CPU image for the reference kernels and tests: width x height texels
// of `channels` values, row-major, no padding.
#pragma once

#include <cstddef>
#include <vector>

namespace asvgf::reference {

template <typename T>
struct Image {
  int width = 0, height = 0, channels = 0;
  std::vector<T> data;

  Image() = default;
  Image(int w, int h, int c, T fill = T{})
      : width(w), height(h), channels(c), data(static_cast<std::size_t>(w) * h * c, fill) {}
  std::size_t index(int x, int y, int c) const {
    return (static_cast<std::size_t>(y) * width + x) * channels + c;
  }
  T& at(int x, int y, int c = 0) { return data[index(x, y, c)]; }
  const T& at(int x, int y, int c = 0) const { return data[index(x, y, c)]; }
  bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
};

using ImageD = Image<double>;

}  // namespace asvgf::reference
