// cpu_oracle/octahedral.hpp: the C++ twin of shaders/common/octahedral.glsl (unit normals as two
// values in [-1,1]). Templated so tests encode in float (as a G-buffer would) and references decode
// in double.
#pragma once

#include <array>
#include <cmath>

namespace asvgf::reference {

template <typename T>
std::array<T, 2> oct_encode(std::array<T, 3> n) {
  const T l1 = std::abs(n[0]) + std::abs(n[1]) + std::abs(n[2]);
  const T x = n[0] / l1, y = n[1] / l1, z = n[2] / l1;
  if (z >= T(0)) return {x, y};
  return {(T(1) - std::abs(y)) * (x >= T(0) ? T(1) : T(-1)), (T(1) - std::abs(x)) * (y >= T(0) ? T(1) : T(-1))};
}

template <typename T>
std::array<T, 3> oct_decode(std::array<T, 2> e) {
  T x = e[0], y = e[1];
  const T z = T(1) - std::abs(x) - std::abs(y);
  if (z < T(0)) {
    const T nx = (T(1) - std::abs(y)) * (x >= T(0) ? T(1) : T(-1));
    const T ny = (T(1) - std::abs(x)) * (y >= T(0) ? T(1) : T(-1));
    x = nx, y = ny;
  }
  const T len = std::sqrt(x * x + y * y + z * z);
  return {x / len, y / len, z / len};
}

}  // namespace asvgf::reference
