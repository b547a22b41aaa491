#!/usr/bin/env bash
# refresh_golden.sh [BUILD_DIR]: copies the reflection JSON of the golden test shaders from a
# build (default: build/) into tests/shaders/golden/. Review the diff before committing it.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
build="${1:-$here/../../build}"
cmake --build "$build" --target asvgf_shaders_generate
for shader in hal_test_scale hal_test_image; do
  cp "$build/shaders/$shader.json" "$here/golden/$shader.json"
  echo "refreshed golden/$shader.json"
done
git -C "$here" diff --stat -- golden || true
