// pbrt_frames AOVS_DIR OUT_PATTERN FIRST COUNT: rewrites frames of an `asvgf render --aovs` folder
// in the channel layout of pbrt-v4's "gbuffer" film (src/pbrt/film.cpp, GBufferFilm::GetImage):
// one single-part EXR a frame holding R, G, B, Albedo.R/G/B, Px/Py/Pz, dzdx, dzdy, Nx/Ny/Nz,
// Nsx/Nsy/Nsz, Variance.R/G/B and RelativeVariance.R/G/B. The colour, albedo, shading normal and
// depth (as Pz, the view depth in pbrt's camera space) are copied as they are; the geometric normal
// repeats the shading normal and every other channel is 0. Lets the suite test `--from pbrt`
// without pbrt; exits 1 with a message when a file cannot be read or written.
#include <tinyexr.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "frame_pattern.hpp"
#include "io/image_io.hpp"

namespace {

// The film's channels, in its order.
// clang-format off
const std::array<const char*, 23> kPbrtChannels = {
    "R", "G", "B", "Albedo.R", "Albedo.G", "Albedo.B", "Px", "Py", "Pz", "dzdx", "dzdy",
    "Nx", "Ny", "Nz", "Nsx", "Nsy", "Nsz",
    "Variance.R", "Variance.G", "Variance.B", "RelativeVariance.R", "RelativeVariance.G", "RelativeVariance.B"};
// clang-format on

void write_pbrt_frame(const std::filesystem::path& dir, int frame, const std::string& out) {
  using asvgf::render::read_exr;
  auto in = [&](const char* buffer) {
    char name[64];
    std::snprintf(name, sizeof(name), "%s_%04d.exr", buffer, frame);
    return read_exr(dir / name);
  };
  const auto color = in("color"), albedo = in("albedo"), normal = in("normal"), depth = in("depth");
  const int w = static_cast<int>(color.width), h = static_cast<int>(color.height);
  const std::size_t pixels = std::size_t(w) * std::size_t(h);
  std::vector<std::vector<float>> planes(kPbrtChannels.size(), std::vector<float>(pixels, 0.0f));
  for (std::size_t p = 0; p < pixels; ++p) {
    for (std::size_t c = 0; c < 3; ++c) {
      planes[0 + c][p] = color.rgba[4 * p + c];
      planes[3 + c][p] = albedo.rgba[4 * p + c];
      planes[11 + c][p] = normal.rgba[4 * p + c];  // Nx..Nz
      planes[14 + c][p] = normal.rgba[4 * p + c];  // Nsx..Nsz
    }
    planes[8][p] = depth.rgba[4 * p];  // Pz
  }
  std::vector<float*> pointers;
  std::vector<EXRChannelInfo> channels(kPbrtChannels.size());
  std::vector<int> types(kPbrtChannels.size(), TINYEXR_PIXELTYPE_FLOAT);
  for (std::size_t c = 0; c < kPbrtChannels.size(); ++c) {
    pointers.push_back(planes[c].data());
    std::snprintf(channels[c].name, sizeof(channels[c].name), "%s", kPbrtChannels[c]);
  }
  EXRImage image;
  InitEXRImage(&image);
  image.num_channels = static_cast<int>(kPbrtChannels.size());
  image.images = reinterpret_cast<unsigned char**>(pointers.data());
  image.width = w;
  image.height = h;
  EXRHeader header;
  InitEXRHeader(&header);
  header.num_channels = image.num_channels;
  header.channels = channels.data();
  header.pixel_types = types.data();
  header.requested_pixel_types = types.data();
  const char* err = nullptr;
  if (SaveEXRImageToFile(&image, &header, out.c_str(), &err) != TINYEXR_SUCCESS) {
    const std::string message = err ? err : "unknown error";
    if (err) FreeEXRErrorMessage(err);
    throw std::runtime_error(out + ": cannot write: " + message);
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: pbrt_frames AOVS_DIR OUT_PATTERN FIRST COUNT\n");
    return 2;
  }
  try {
    const int first = std::atoi(argv[3]), count = std::atoi(argv[4]);
    for (int f = first; f < first + count; ++f) write_pbrt_frame(argv[1], f, expand_frame_pattern(argv[2], f));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pbrt_frames: %s\n", e.what());
    return 1;
  }
  std::printf("pbrt_frames: wrote %s frames\n", argv[4]);
  return 0;
}
