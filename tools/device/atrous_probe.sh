#!/usr/bin/env bash
# Builds the à-trous probes of `measure.sh atrous` and `atrous-quality` (issue 36): one binary for
# each patch in tools/device/atrous_probes/, .devbin/asvgf_atrous_<NAME>.
#   t13   the B3 kernel's 13 taps with |i| + |j| <= 2 (the default's 21 less the 8 at (2, 1) and
#         the like: 14.1% of the B3 spline's weight left out, 1.6% in the default); measured 17% faster than 21 at 1080p
#         with the same error but a lag of 2 frames where 21 has 0 (docs/performance.md, "Fewer taps")
# The per-tap arithmetic bounds each iteration, so fewer taps are faster; a patch changes the frames
# (the CPU reference with them: the frame-hash test is the one that fails), so `atrous-quality`
# measures what it costs at 1080p. The sources are patched for each
# build and restored afterwards (also when a build fails), then the normal binary is rebuilt.
#   bash tools/device/atrous_probe.sh
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
source tools/device/patched_sources.sh
keep_sources shaders/denoise/atrous.comp pipeline/cpu_oracle/denoise_reference.cpp
mkdir -p .devbin
for patch in tools/device/atrous_probes/*.patch; do
  name=$(basename "$patch" .patch)
  reset_sources
  git apply "$patch" || { echo "atrous_probe.sh: $patch no longer applies: update it" >&2; exit 1; }
  cmake --build --preset default > /dev/null
  strip -o ".devbin/asvgf_atrous_$name" build/bin/asvgf
  echo "atrous_probe.sh: .devbin/asvgf_atrous_$name"
done
