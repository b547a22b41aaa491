#!/usr/bin/env bash
# Builds the probe binaries of one family for measure.sh: .devbin/asvgf_<FAMILY>_<NAME> from each
# tools/device/<FAMILY>_probes/<NAME>.patch. The sources a family's patches touch are saved,
# patched for each build and restored afterwards (also when a build fails), then the normal binary
# is rebuilt.
#   bash tools/device/build_probes.sh atrous   # measure.sh atrous, atrous-quality (issue 36)
#   bash tools/device/build_probes.sh glossy   # measure.sh glossy-probe (issue 39)
# atrous: none now (13 taps, `nozero`, `bounds2` and `boxsep` became the defaults, `nseries`,
#   `novarpf` and `box4` were measured and dropped: docs/performance.md, "Fewer taps", "What a tap's
#   instructions cost", "The local mean's box over blocks, separable"). A patch that changes the
#   frames (the CPU reference with them: the frame-hash test is the one that fails) needs
#   `atrous-quality` to measure what it costs at 1080p.
# glossy (docs/quality.md, "The specular chain's own correction at 1080p, and a stricter gate"):
#   speclm  the specular chain of --specular-split with its own local-mean correction (its tapped
#           history's and its result's), as the diffuse chain has: at 1080p the split's glossy
#           error -20% (boxes-move) and -14% (orbit), at 256x256 +31%
#   gate    the correction's gate in its Wiener form, max(d^2 - se^2, 0) / d^2 (shader and CPU
#           reference): measured at 64x64 and 256x256 only
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
source tools/device/patched_sources.sh
family=${1:?usage: build_probes.sh FAMILY (a folder tools/device/FAMILY_probes)}
patches=(tools/device/"${family}"_probes/*.patch)
[ -e "${patches[0]}" ] || { echo "build_probes.sh: no patches in tools/device/${family}_probes" >&2; exit 1; }
mapfile -t touched < <(sed -n 's|^+++ b/||p' "${patches[@]}" | sort -u)
keep_sources "${touched[@]}"
mkdir -p .devbin
for patch in "${patches[@]}"; do
  name=$(basename "$patch" .patch)
  reset_sources
  git apply "$patch" || { echo "build_probes.sh: $patch no longer applies: update it" >&2; exit 1; }
  cmake --build --preset default > /dev/null
  strip -o ".devbin/asvgf_${family}_$name" build/bin/asvgf
  echo "build_probes.sh: .devbin/asvgf_${family}_$name"
done
