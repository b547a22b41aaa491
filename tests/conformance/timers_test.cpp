// Timers: a timed region reports positive finite milliseconds, or nothing at all, never zero.
#include <cmath>

#include "backends.hpp"

using namespace conformance;
using hal::State;

TEST_CASE("conformance: timers give positive finite milliseconds or none") {
  for_each_backend([](hal::Device& device) {
    const auto timers = device.create_timer_queries({"timers", 3});
    // Never recorded: no time.
    for (const auto& t : device.read_timers(timers)) CHECK_FALSE(t.has_value());

    const std::uint64_t size = 16u << 20;
    const auto usage = hal::BufferUsage::CopySrc | hal::BufferUsage::CopyDst;
    const auto a = device.create_buffer({"timed a", size, usage});
    const auto b = device.create_buffer({"timed b", size, usage});
    auto cmd = device.create_command_list("timed");
    cmd->begin_label("timed work");
    cmd->begin_timer(timers, 0);
    cmd->barrier({a, State::Undefined, State::CopyDst});
    cmd->clear_buffer(a, 7);
    cmd->barrier({a, State::CopyDst, State::CopySrc});
    cmd->end_timer(timers, 0);
    cmd->begin_timer(timers, 2);
    cmd->barrier({b, State::Undefined, State::CopyDst});
    cmd->copy_buffer({a, b, 0, 0, size});
    cmd->end_timer(timers, 2);
    cmd->end_label();
    device.submit(*cmd);
    device.wait();

    const auto times = device.read_timers(timers);
    REQUIRE(times.size() == 3);
    CHECK_FALSE(times[1].has_value());  // region 1 was not recorded
    if (device.capabilities().timestamps) {
      for (int r : {0, 2}) {
        REQUIRE(times[r].has_value());
        CHECK(std::isfinite(*times[r]));
        CHECK(*times[r] > 0.0);
        CHECK(*times[r] < 10000.0);
      }
    } else {
      for (const auto& t : times) CHECK_FALSE(t.has_value());
    }
  });
}
