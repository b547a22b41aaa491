#!/usr/bin/env bash
# Builds the binary of `measure.sh resident` (issue 37): asvgf whose path tracer counts its resident
# workgroups. The first invocation of each workgroup adds 1 to a counter at its start (raising a
# maximum beside it) and subtracts 1 at its end, in the ray-counter buffer's spare words; the
# renderer prints the maximum every frame ("resident path-tracing workgroups: N") on stderr. N over
# the GPU's multiprocessors (132 on the H100 and H200) is the workgroups a SM the compiled program
# gets: what OpenGL does not report and Vulkan does only as registers (docs/performance.md, "The
# path tracer's occupancy"). The sources are patched for the build and restored afterwards (also
# when it fails), then the normal binary is rebuilt. Output: .devbin/asvgf_resident (stripped).
#   bash tools/device/resident_probe.sh
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
source tools/device/patched_sources.sh
keep_sources shaders/renderer/pathtrace.comp pipeline/renderer/renderer.cpp pipeline/renderer/frame_graph.cpp
python3 - <<'PY'
import sys
sys.path.insert(0, "tools/device")
from patch_source import patch
patch("resident_probe.sh", "shaders/renderer/pathtrace.comp", [
    ("buffer RayCounter { uint count; } ray_counter;",
     "buffer RayCounter { uint count; uint resident; uint most_resident; uint pad; } ray_counter;"),
    ("  if (gl_LocalInvocationIndex == 0u) group_rays = 0u;\n",
     "  if (gl_LocalInvocationIndex == 0u) {\n    group_rays = 0u;\n"
     "    atomicMax(ray_counter.most_resident, atomicAdd(ray_counter.resident, 1u) + 1u);\n  }\n"),
    ("  if (gl_LocalInvocationIndex == 0u && group_rays > 0u) atomicAdd(ray_counter.count, group_rays);\n",
     "  if (gl_LocalInvocationIndex == 0u && group_rays > 0u) atomicAdd(ray_counter.count, group_rays);\n"
     "  if (gl_LocalInvocationIndex == 0u) atomicAdd(ray_counter.resident, 0xFFFFFFFFu);\n"),
])
patch("resident_probe.sh", "pipeline/renderer/frame_graph.cpp", [
    ("constexpr std::uint64_t kRayCounterSize = 4;", "constexpr std::uint64_t kRayCounterSize = 16;"),
])
patch("resident_probe.sh", "pipeline/renderer/renderer.cpp", [
    ("  std::uint32_t rays = 0;\n"
     "  device_.read_buffer(targets_.ray_counter, 0, std::as_writable_bytes(std::span(&rays, 1)));\n",
     "  std::array<std::uint32_t, 4> counter{};\n"
     "  device_.read_buffer(targets_.ray_counter, 0, std::as_writable_bytes(std::span(counter)));\n"
     "  const std::uint32_t rays = counter[0];\n"
     "  std::fprintf(stderr, \"resident path-tracing workgroups: %u\\n\", counter[2]);\n"),
])
PY
cmake --build --preset default > /dev/null
mkdir -p .devbin
strip -o .devbin/asvgf_resident build/bin/asvgf
echo "resident_probe.sh: .devbin/asvgf_resident"
