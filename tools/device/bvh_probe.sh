#!/usr/bin/env bash
# Builds the binaries of `measure.sh bvh` (issue 36's frame, issue 37's path tracing): asvgf with the
# BVH builder's leaf rules changed, one binary per variant, into .devbin/asvgf_bvh<LEAF>x<CAP>
# (stripped). LEAF is the size at which the builder always makes a leaf (BvhOptions::
# max_leaf_triangles, 3 as built), CAP the multiple of it up to which the SAH may still choose one
# (4 as built: leaves of up to 12). Frames do not depend on the tree (docs/performance.md, "The BVH's
# leaves"). The sources are patched for each build and restored afterwards (also when a build
# fails), then the normal binary is rebuilt.
#   bash tools/device/bvh_probe.sh [LEAF:CAP...]   (default 2:4 4:4)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
source tools/device/patched_sources.sh
keep_sources pipeline/renderer/bvh.hpp pipeline/renderer/bvh.cpp
variants=("$@")
[ ${#variants[@]} -gt 0 ] || variants=(2:4 4:4)
mkdir -p .devbin
for variant in "${variants[@]}"; do
  leaf=${variant%%:*} cap=${variant##*:}
  reset_sources
  python3 - "$leaf" "$cap" <<'PY'
import sys
sys.path.insert(0, "tools/device")
from patch_source import patch_once
leaf, cap = sys.argv[1], sys.argv[2]
patch_once("bvh_probe.sh", "pipeline/renderer/bvh.hpp", "std::uint32_t max_leaf_triangles = 3;", "std::uint32_t max_leaf_triangles = %s;" % leaf)
patch_once("bvh_probe.sh", "pipeline/renderer/bvh.cpp", "if (n <= 4 * options.max_leaf_triangles || best_axis < 0) return make_leaf();",
      "if (n <= %s * options.max_leaf_triangles || best_axis < 0) return make_leaf();" % cap)
PY
  cmake --build --preset default > /dev/null
  strip -o ".devbin/asvgf_bvh${leaf}x${cap}" build/bin/asvgf
  echo "bvh_probe.sh: .devbin/asvgf_bvh${leaf}x${cap} (leaves forced at $leaf triangles, the SAH's up to $((leaf * cap)))"
done
