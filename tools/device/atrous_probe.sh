#!/usr/bin/env bash
# Builds the à-trous probes of `measure.sh atrous` (issue 36), which no GPU could time when they were
# written: one binary for each patch in tools/device/atrous_probes/, .devbin/asvgf_atrous_<NAME>.
#   uniform_inside  the taps' bounds tests and the prefilter's clamps behind one uniform test a
#                   workgroup (whether all its taps lie inside the image), in the one tap loop
#   pairs           that, and the default chain's packed-in iterations (atrous.2 to .5 at 1080p)
#                   filtering two pixels an invocation, p and p + (step, 0), from one pass over
#                   their 6x5 taps (30 tap loads for two pixels instead of 50); its test changes
#                   come with it (`git apply` it to land it)
# Both give frames bit-identical to this build's on lavapipe (the packed-texel, block-sum and
# frame-hash tests). The sources are patched for each build and restored afterwards (also when a
# build fails), then the normal binary is rebuilt.
#   bash tools/device/atrous_probe.sh
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
source tools/device/patched_sources.sh
keep_sources shaders/denoise/atrous.comp shaders/denoise/shaders.cmake pipeline/denoiser/passes/atrous.cpp \
  tests/pipeline/denoise_passes_test.cpp
mkdir -p .devbin
for patch in tools/device/atrous_probes/*.patch; do
  name=$(basename "$patch" .patch)
  reset_sources
  git apply "$patch" || { echo "atrous_probe.sh: $patch no longer applies: update it" >&2; exit 1; }
  cmake --build --preset default > /dev/null
  strip -o ".devbin/asvgf_atrous_$name" build/bin/asvgf
  echo "atrous_probe.sh: .devbin/asvgf_atrous_$name"
done
