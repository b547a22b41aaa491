// denoiser/api/input_report.hpp: the validate option's counts (denoiser/passes/validate_inputs.hpp) as an
// asvgf::InputReport with its problems in words.
#pragma once

#include <array>
#include <cstdint>

#include "asvgf/denoiser.hpp"
#include "denoiser/passes/validate_inputs.hpp"

namespace asvgf::api {

InputReport make_input_report(const std::array<std::uint32_t, passes::kInputCounts>& counts);

}  // namespace asvgf::api
