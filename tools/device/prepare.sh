#!/usr/bin/env bash
# Prepares a run on a machine with an NVIDIA GPU that has no package registry (the `device` tool,
# Ubuntu 24.04): the amd64 Vulkan/GL loader packages in .gl/ and our build's asvgf with the Debian
# libraries it links in .devbin/, both ignored by git (added to .git/info/exclude here) and named in
# the run's `carry`. Run here, as root, after `cmake --build --preset default`:
#   bash tools/device/prepare.sh
# then on the device: `bash tools/device/measure.sh [STEP...]` (see that file).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
[ -x build/bin/asvgf ] || { echo "prepare.sh: build/bin/asvgf missing: build first" >&2; exit 1; }
mkdir -p .git/info
for path in /.gl/ /.devbin/; do grep -qxF "$path" .git/info/exclude 2>/dev/null || echo "$path" >> .git/info/exclude; done
if ! ls .gl/libvulkan1_*.deb >/dev/null 2>&1; then
  lists=/tmp/amd64-lists
  apt=(-oAPT::Architecture=amd64 -oAPT::Architectures=amd64 -oDir::State::Lists=$lists)
  mkdir -p .gl "$lists/partial"
  apt-get "${apt[@]}" update -qq
  (cd .gl && apt-get "${apt[@]}" download libvulkan1 libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2)
fi
mkdir -p .devbin/lib
strip -o .devbin/asvgf build/bin/asvgf  # 9 MB against 24 with debug info: the carry limit is 64 MiB
cp build/bin/exr_compare .devbin/exr_compare  # measure.sh local-mean
# The libraries Ubuntu's image lacks: what asvgf links from Debian beyond the loaders and libc.
for lib in libepoxy.so.0 libtinyobjloader.so.2rc10 libtinygltf.so.2d libtinyexr.so.1d libstb.so.0; do
  cp -L "/lib/x86_64-linux-gnu/$lib" .devbin/lib/
done
echo "prepare.sh: .gl/ and .devbin/ ready; carry [\".gl\", \".devbin\"]"
