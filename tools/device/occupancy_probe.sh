#!/usr/bin/env bash
# Builds the binaries of `measure.sh vk-occupancy` (issue 37): asvgf with shared memory that does
# nothing but limit how many path-tracer workgroups fit on an SM (H100/H200: 228 KB each), one
# binary per size, into .devbin/asvgf_vkpad<WORDS> (stripped). pathtrace.comp is patched for each
# build and restored afterwards (also when a build fails), then the normal binary is rebuilt.
#   bash tools/device/occupancy_probe.sh [WORDS...]   (default 7168 12032: 28 and 47 KB, at most 8
#                                                      and 4 workgroups a SM; NVIDIA allows 48 KB)
# Lavapipe does not refuse these sizes (its limit is 32 KB), so a render here checks the build only.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
shader=shaders/renderer/pathtrace.comp
saved=$(mktemp)
cp "$shader" "$saved"
restore() {
  cp "$saved" "$shader"
  rm -f "$saved"
  cmake --build --preset default > /dev/null
}
trap restore EXIT
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(7168 12032)
mkdir -p .devbin
for words in "${sizes[@]}"; do
  cp "$saved" "$shader"
  # The array is written by invocation 0 and read into the ray count, so no compiler removes it.
  python3 - "$shader" "$words" <<'EOF'
import sys
path, words = sys.argv[1], sys.argv[2]
s = open(path).read()
edits = [
    ("shared uint group_rays;\n",
     "shared uint group_rays;\nshared uint occupancy_pad[%su];\n" % words),
    ("  if (gl_LocalInvocationIndex == 0u) group_rays = 0u;\n",
     "  if (gl_LocalInvocationIndex == 0u) {\n    group_rays = 0u;\n"
     "    occupancy_pad[gl_WorkGroupID.x %% %su] = gl_WorkGroupID.y;\n  }\n" % words),
    ("atomicAdd(ray_counter.count, group_rays);",
     "atomicAdd(ray_counter.count, group_rays + (occupancy_pad[gl_WorkGroupID.x %% %su] == 0xFFFFFFFFu ? 1u : 0u));"
     % words),
]
for old, new in edits:
    if s.count(old) != 1:
        sys.exit("occupancy_probe.sh: pathtrace.comp no longer has '%s' once: update the patch" % old.strip())
    s = s.replace(old, new)
open(path, "w").write(s)
EOF
  cmake --build --preset default > /dev/null
  strip -o ".devbin/asvgf_vkpad$words" build/bin/asvgf
  echo "occupancy_probe.sh: .devbin/asvgf_vkpad$words ($((words * 4 / 1024)) KB of shared memory a workgroup)"
done
