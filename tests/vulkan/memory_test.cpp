// The sub-allocation logic of hal_vulkan's memory allocator, without a GPU.
#include <doctest/doctest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "memory.hpp"

using hal::vulkan::RangeAllocator;

TEST_CASE("range allocator: aligned allocations do not overlap and free coalesces") {
  RangeAllocator ranges(1024);
  const auto a = ranges.allocate(100, 1);
  const auto b = ranges.allocate(100, 256);
  const auto c = ranges.allocate(50, 64);
  REQUIRE(a);
  REQUIRE(b);
  REQUIRE(c);
  CHECK(*a == 0);
  CHECK(*b % 256 == 0);
  CHECK(*c % 64 == 0);
  CHECK(ranges.used() == 250);
  // Padding in front of b stays free: a small allocation fits in it.
  const auto d = ranges.allocate(16, 16);
  REQUIRE(d);
  CHECK(*d >= 100);
  CHECK(*d + 16 <= *b);
  for (auto offset : {*a, *b, *c, *d}) CHECK(ranges.free(offset));
  CHECK(ranges.empty());
  CHECK(ranges.used() == 0);
  CHECK(ranges.free_range_count() == 1);
  CHECK(ranges.largest_free_range() == 1024);
}

TEST_CASE("range allocator: rejects what cannot fit and bad requests") {
  RangeAllocator ranges(256);
  CHECK_FALSE(ranges.allocate(0, 1));
  CHECK_FALSE(ranges.allocate(16, 3));  // not a power of two
  CHECK_FALSE(ranges.allocate(257, 1));
  const auto all = ranges.allocate(256, 1);
  REQUIRE(all);
  CHECK_FALSE(ranges.allocate(1, 1));
  CHECK_FALSE(ranges.free(12345));
  CHECK(ranges.free(*all));
  CHECK_FALSE(ranges.free(*all));  // double free is reported, not corrupting
  CHECK(ranges.allocate(256, 256));
}

TEST_CASE("range allocator: best fit keeps the large range whole") {
  RangeAllocator ranges(1000);
  const auto a = ranges.allocate(100, 1);  // [0,100)
  const auto b = ranges.allocate(100, 1);  // [100,200)
  const auto c = ranges.allocate(100, 1);  // [200,300), leaves [300,1000)
  REQUIRE((a && b && c));
  ranges.free(*b);  // hole of 100
  const auto d = ranges.allocate(80, 1);
  REQUIRE(d);
  CHECK(*d == 100);  // the hole, not the big tail
  CHECK(ranges.largest_free_range() == 700);
}

TEST_CASE("range allocator: random allocate/free keeps ranges disjoint and accounting exact") {
  RangeAllocator ranges(1 << 20);
  std::mt19937 rng(7);
  struct Live {
    std::uint64_t offset, size;
  };
  std::vector<Live> live;
  std::uint64_t used = 0;
  for (int step = 0; step < 5000; ++step) {
    if (live.empty() || rng() % 3 != 0) {
      const std::uint64_t size = 1 + rng() % 8192;
      const std::uint64_t alignment = std::uint64_t{1} << (rng() % 9);
      if (const auto offset = ranges.allocate(size, alignment)) {
        CHECK(*offset % alignment == 0);
        CHECK(*offset + size <= ranges.capacity());
        live.push_back({*offset, size});
        used += size;
      }
    } else {
      const std::size_t i = rng() % live.size();
      CHECK(ranges.free(live[i].offset));
      used -= live[i].size;
      live.erase(live.begin() + static_cast<std::ptrdiff_t>(i));
    }
    REQUIRE(ranges.used() == used);
  }
  std::sort(live.begin(), live.end(), [](const Live& x, const Live& y) { return x.offset < y.offset; });
  for (std::size_t i = 1; i < live.size(); ++i) CHECK(live[i - 1].offset + live[i - 1].size <= live[i].offset);
  for (const auto& l : live) CHECK(ranges.free(l.offset));
  CHECK(ranges.free_range_count() == 1);
  CHECK(ranges.largest_free_range() == ranges.capacity());
}
