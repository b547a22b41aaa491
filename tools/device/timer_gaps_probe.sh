#!/usr/bin/env bash
# Builds the binary of `measure.sh gaps` (issue 37's small passes): asvgf whose GPU timers give each
# pass the time from the previous pass's end to its own end instead of from its own begin, on
# Vulkan and OpenGL alike. A pass's barrier is recorded before its begin timestamp; Vulkan writes
# that timestamp after the barrier's wait (ALL_COMMANDS), while OpenGL may apply glMemoryBarrier
# lazily at the next dispatch, inside the pass's region. Counting from the previous end puts each
# barrier's cost into the pass after it on both APIs, so that small passes compare like for like
# (the frame's sum becomes its span). The sources are patched for the build and restored
# afterwards (also when it fails), then the normal binary is rebuilt. Output: .devbin/asvgf_gaps.
#   bash tools/device/timer_gaps_probe.sh
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
source tools/device/patched_sources.sh
keep_sources hal_vulkan/src/timers.cpp hal_gl/src/device.cpp
python3 - <<'PY'
import sys
sys.path.insert(0, "tools/device")
from patch_source import patch_once
patch_once("timer_gaps_probe.sh", "hal_vulkan/src/timers.cpp",
      "    const std::uint64_t ticks = (values[2] - values[0]) & mask;",
      "    std::uint64_t previous_end[2] = {};  // value, available\n"
      "    if (r > 0 && t.submitted[r - 1] &&\n"
      "        vkGetQueryPoolResults(device_, t.pool, 2 * r - 1, 1, sizeof previous_end, previous_end,\n"
      "                              2 * sizeof(std::uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WITH_AVAILABILITY_BIT) ==\n"
      "            VK_SUCCESS &&\n"
      "        previous_end[1])\n"
      "      values[0] = previous_end[0];\n"
      "    const std::uint64_t ticks = (values[2] - values[0]) & mask;")
patch_once("timer_gaps_probe.sh", "hal_gl/src/device.cpp",
      "    if (end >= begin) times[r] = static_cast<double>(end - begin) * 1e-6;",
      "    if (r > 0 && t.written[r - 1]) {\n"
      "      if (es)\n"
      "        glGetQueryObjectui64vEXT(t.queries[2 * r - 1], GL_QUERY_RESULT, &begin);\n"
      "      else\n"
      "        glGetQueryObjectui64v(t.queries[2 * r - 1], GL_QUERY_RESULT, &begin);\n"
      "    }\n"
      "    if (end >= begin) times[r] = static_cast<double>(end - begin) * 1e-6;")
PY
cmake --build --preset default > /dev/null
mkdir -p .devbin
strip -o .devbin/asvgf_gaps build/bin/asvgf
echo "timer_gaps_probe.sh: .devbin/asvgf_gaps (each pass timed from the previous pass's end)"
