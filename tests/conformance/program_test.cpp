// The backends agree on what a correct program is: no report (recording HAL), no validation
// message and the expected values (executing backends).
#include "backends.hpp"
#include "program.hpp"

using namespace conformance;

TEST_CASE("conformance: a multi-dispatch program is clean on every backend") {
  for_every_backend([](hal::Device& device, bool executes) {
    std::vector<float> input(300);
    for (std::size_t i = 0; i < input.size(); ++i) input[i] = static_cast<float>(i) - 100.0f;
    const auto out = run_multi_dispatch_program(device, input);
    if (!executes) return;  // the recording HAL's verdict is its reports, checked by TestDevice
    int wrong = 0;
    for (std::size_t i = 0; i < input.size(); ++i)
      if (out[i] != (input[i] * 2.0f + 1.0f) * 0.5f - 3.0f) ++wrong;
    CHECK(wrong == 0);
  });
}
