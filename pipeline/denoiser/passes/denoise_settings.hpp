// denoiser/passes/denoise_settings.hpp: the denoiser's parameters, defined in the public header
// include/asvgf/denoise_settings.hpp and named here as the passes use them.
#pragma once

#include "asvgf/denoise_settings.hpp"

namespace asvgf::passes {

using asvgf::AtrousKernel;
using asvgf::DenoiseSettings;
using asvgf::GradientSource;
using asvgf::Tonemap;

}  // namespace asvgf::passes
