// `asvgf denoise`'s input checks: file patterns, what a frame's EXR must hold (errors naming the
// file, the channel and the pixel), and the motion-convention check on synthetic frames.
#include <doctest/doctest.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "frame_sequence.hpp"
#include "motion_check.hpp"
#include "io/image_io.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wshadow"
#include <tinyexr.h>
#pragma GCC diagnostic pop

using namespace asvgf;

namespace {

std::filesystem::path temp_dir() {
  auto dir = std::filesystem::temp_directory_path() / "asvgf_denoise_inputs_test";
  std::filesystem::create_directories(dir);
  return dir;
}

// An EXR with exactly the named float channels (SaveEXR always writes RGB(A) or one channel),
// written with the low-level API so that any channel set and any value (NaN too) can be stored.
void write_channels(const std::filesystem::path& path, int w, int h, const std::vector<std::string>& names,
                    const std::vector<std::vector<float>>& planes) {
  EXRHeader header;
  InitEXRHeader(&header);
  EXRImage image;
  InitEXRImage(&image);
  std::vector<const float*> pointers;
  for (const auto& p : planes) pointers.push_back(p.data());
  image.num_channels = static_cast<int>(names.size());
  image.images = reinterpret_cast<unsigned char**>(const_cast<float**>(pointers.data()));
  image.width = w;
  image.height = h;
  std::vector<EXRChannelInfo> infos(names.size());
  std::vector<int> types(names.size(), TINYEXR_PIXELTYPE_FLOAT);
  for (std::size_t i = 0; i < names.size(); ++i)
    std::snprintf(infos[i].name, sizeof infos[i].name, "%s", names[i].c_str());
  header.num_channels = static_cast<int>(names.size());
  header.channels = infos.data();
  header.pixel_types = types.data();
  header.requested_pixel_types = types.data();
  const char* err = nullptr;
  REQUIRE(SaveEXRImageToFile(&image, &header, path.c_str(), &err) == TINYEXR_SUCCESS);
}

std::string error_of(const cli::FramePattern& pattern, int frame, const cli::BufferSpec& spec) {
  try {
    cli::read_frame(pattern, frame, spec);
  } catch (const render::ImageIoError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("denoise inputs: a pattern needs exactly one frame number and expands it") {
  CHECK(cli::FramePattern("--color", "f/color_%04d.exr").path(7) == std::filesystem::path("f/color_0007.exr"));
  CHECK(cli::FramePattern("--color", "c%d_100%%.exr").path(12) == std::filesystem::path("c12_100%.exr"));
  CHECK_THROWS_AS(cli::FramePattern("--color", "color.exr"), CLI::ValidationError);
  CHECK_THROWS_AS(cli::FramePattern("--color", "%d_%d.exr"), CLI::ValidationError);
  CHECK_THROWS_AS(cli::FramePattern("--color", "%s.exr"), CLI::ValidationError);
  CHECK_THROWS_AS(cli::FramePattern("--color", "%0100d.exr"), CLI::ValidationError);
  CHECK(cli::FramePattern("--color", "%040d").path(3).string() == std::string(39, '0') + "3");
}

TEST_CASE("denoise inputs: a frame's EXR is refused naming the file for a missing channel, a size or a NaN") {
  const auto dir = temp_dir();
  const int w = 5, h = 3;
  std::vector<float> plane(w * h, 1.0f);
  write_channels(dir / "one_0000.exr", w, h, {"R"}, {plane});
  write_channels(dir / "rg_0000.exr", w, h, {"G", "R"}, {plane, plane});
  std::vector<float> with_nan = plane;
  with_nan[2 * w + 3] = std::numeric_limits<float>::quiet_NaN();
  write_channels(dir / "nan_0000.exr", w, h, {"G", "R"}, {with_nan, plane});  // NaN in G at (3, 2)

  const cli::FramePattern one("--depth", (dir / "one_%04d.exr").string());
  const cli::FramePattern rg("--motion", (dir / "rg_%04d.exr").string());
  const cli::FramePattern nan("--motion", (dir / "nan_%04d.exr").string());
  CHECK(error_of(one, 0, {"depth", w, h, {"R"}}).empty());
  CHECK(error_of(rg, 0, {"motion", w, h, {"R", "G"}}).empty());
  write_channels(dir / "rb_0000.exr", w, h, {"B", "R"}, {plane, plane});
  const cli::FramePattern rb("--motion", (dir / "rb_%04d.exr").string());
  CHECK(error_of(rb, 0, {"motion", w, h, {"R", "G"}}).find("rb_0000.exr (motion, frame 0): no channel G") !=
        std::string::npos);
  CHECK(error_of(rg, 0, {"motion", 6, 3, {"R", "G"}}).find("5x3, expected 6x3") != std::string::npos);
  CHECK(error_of(nan, 0, {"motion", w, h, {"R", "G"}}).find("NaN in channel G at pixel (3, 2)") != std::string::npos);
  CHECK(error_of(rg, 1, {"motion", w, h, {"R", "G"}}).find("rg_0001.exr (motion, frame 1): missing") !=
        std::string::npos);
  // A grey file (one channel of any name) reads as R = G = B; depth may hold +-Inf (background).
  write_channels(dir / "z_0000.exr", w, h, {"Z"}, {plane});
  CHECK(error_of(cli::FramePattern("--depth", (dir / "z_%04d.exr").string()), 0, {"depth", w, h, {"R"}}).empty());
  std::vector<float> with_inf = plane;
  with_inf[1] = std::numeric_limits<float>::infinity();
  write_channels(dir / "inf_0000.exr", w, h, {"R"}, {with_inf});
  const cli::FramePattern inf("--depth", (dir / "inf_%04d.exr").string());
  CHECK(error_of(inf, 0, {"depth", w, h, {"R"}, true}).empty());
  CHECK(error_of(inf, 0, {"color", w, h, {"R"}}).find("Inf in channel R at pixel (1, 0)") != std::string::npos);
  CHECK(cli::count_frames(rg, 0) == 1);
  CHECK(cli::count_frames(rg, 1) == 0);
}

namespace {

// Two frames of a scene sliding right by `shift` pixels: a staircase of depths (1, 2, 3, ...,
// changing every 4 columns) so that landing on the wrong column gives another depth.
struct Frames {
  int w = 48, h = 16;
  std::vector<float> previous_depth, depth, motion;
};
Frames sliding(int shift, float mx_scale, float my) {
  Frames f;
  auto z = [](int x) { return 1.0f + static_cast<float>(((x % 40) + 40) % 40 / 4); };
  f.previous_depth.assign(f.w * f.h * 4, 0.0f);
  f.depth = f.motion = f.previous_depth;
  for (int y = 0; y < f.h; ++y)
    for (int x = 0; x < f.w; ++x) {
      const std::size_t i = (std::size_t(y) * f.w + x) * 4;
      f.previous_depth[i] = z(x);
      f.depth[i] = z(x - shift);                            // what was at x - shift is now at x
      f.motion[i] = -static_cast<float>(shift) * mx_scale;  // previous minus current, scaled
      f.motion[i + 1] = my;
    }
  return f;
}

}  // namespace

TEST_CASE("denoise inputs: the motion check accepts the convention and names the sign, unit and y-axis mistakes") {
  const Frames right = sliding(6, 1.0f, 0.0f);
  const auto ok = cli::check_motion(right.previous_depth, right.depth, right.motion, 48, 16);
  CHECK(ok.moving_pixels == 48 * 16);
  CHECK(!ok.problem);
  CHECK(ok.as_given.consistent > 0.8);

  const Frames negated = sliding(6, -1.0f, 0.0f);
  const auto neg = cli::check_motion(negated.previous_depth, negated.depth, negated.motion, 48, 16);
  REQUIRE(neg.problem);
  CHECK(neg.best.convention == "negated");
  CHECK(
      neg.problem->find("Read them with --motion-sign current-minus-previous --motion-units pixels --motion-y down") !=
      std::string::npos);

  const Frames uv = sliding(6, 1.0f / 48.0f, 0.0f);
  const auto in_uv = cli::check_motion(uv.previous_depth, uv.depth, uv.motion, 48, 16);
  REQUIRE(in_uv.problem);
  CHECK(in_uv.best.convention == "in UV units");

  // A scene sliding right and down (depth changes along x and y): vectors written with y up look
  // y-flipped, and the setting that reads them is named.
  Frames diagonal;
  for (auto* v : {&diagonal.previous_depth, &diagonal.depth, &diagonal.motion})
    v->assign(std::size_t(diagonal.w) * diagonal.h * 4, 0.0f);
  auto zxy = [](int x, int y) {
    return 1.0f + static_cast<float>((((x / 4) % 5 + 5) % 5) + 5 * (((y / 2) % 4 + 4) % 4));
  };
  for (int y = 0; y < diagonal.h; ++y)
    for (int x = 0; x < diagonal.w; ++x) {
      const std::size_t i = (std::size_t(y) * diagonal.w + x) * 4;
      diagonal.previous_depth[i] = zxy(x, y);
      diagonal.depth[i] = zxy(x - 2, y - 3);
      diagonal.motion[i] = -2.0f;
      diagonal.motion[i + 1] = 3.0f;  // previous minus current is -3 with y down: +3 is y up
    }
  const auto flipped = cli::check_motion(diagonal.previous_depth, diagonal.depth, diagonal.motion, 48, 16);
  REQUIRE(flipped.problem);
  CHECK(flipped.best.convention == "y-flipped");
  CHECK(flipped.problem->find("--motion-y up") != std::string::npos);
  // Given as Cycles' convention (y up) and converted, the same vectors are right.
  for (std::size_t i = 1; i < diagonal.motion.size(); i += 4) diagonal.motion[i] = -diagonal.motion[i];
  CHECK(!cli::check_motion(diagonal.previous_depth, diagonal.depth, diagonal.motion, 48, 16,
                           asvgf::MotionConvention::cycles())
             .problem);

  const Frames still = sliding(0, 1.0f, 0.0f);
  const auto none = cli::check_motion(still.previous_depth, still.depth, still.motion, 48, 16);
  CHECK(none.moving_pixels == 0);
  CHECK(!none.problem);
}
