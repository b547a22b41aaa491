#!/usr/bin/env bash
# tools/fuzz.sh [SECONDS] [TARGET...]: builds the libFuzzer targets of tests/fuzz with clang (ASan +
# UBSan) into build-fuzz/ and runs each for SECONDS (default 60) on a copy of its seed corpus in
# tests/fuzz/corpus/<target>/. A crash, leak or sanitizer report stops the run, leaves the input in
# build-fuzz/findings/<target>/ and exits 1; make it a regression test (tests/data/fuzz_regressions/).
# Targets: scene_json obj gltf image reflection (default: all). ASVGF_FUZZ_SEED=N fixes libFuzzer's
# random seed (CI does, so that a red run replays); unset, each run explores differently.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
seconds="${1:-60}"
shift || true
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(scene_json obj gltf image reflection)
if ! command -v clang++ >/dev/null; then
  echo "tools/fuzz.sh: clang++ not found (tools/bootstrap.sh installs clang and libclang-rt-14-dev)" >&2
  exit 1
fi
cmake -S tests/fuzz -B build-fuzz -G Ninja -DCMAKE_CXX_COMPILER=clang++ >/dev/null
cmake --build build-fuzz -j2
status=0
for t in "${targets[@]}"; do
  corpus="build-fuzz/corpus/$t"
  findings="build-fuzz/findings/$t"
  mkdir -p "$corpus" "$findings"
  cp -n tests/fuzz/corpus/"$t"/* "$corpus"/ 2>/dev/null || true
  echo "fuzz: $t for ${seconds} s"
  if ! ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1:suppressions=tests/fuzz/ubsan.supp \
      "build-fuzz/fuzz_$t" -max_total_time="$seconds" -seed="${ASVGF_FUZZ_SEED:-0}" -timeout=10 -rss_limit_mb=2048 \
      -artifact_prefix="$findings/" -print_final_stats=1 "$corpus" 2>"build-fuzz/$t.log"; then
    echo "fuzz: $t FOUND a problem: see build-fuzz/$t.log and $findings/" >&2
    # What it found, in CI's log too: the sanitizer's report head, the artifact and its bytes (Base64).
    grep -E "^==[0-9]+==|SUMMARY|deadly signal|timeout|out-of-memory|leak|Test unit written|^Base64:" "build-fuzz/$t.log" |
      head -n 30 | sed "s/^/fuzz: $t: /" >&2 || true
    status=1
  fi
  grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "build-fuzz/$t.log" | sed "s/^/fuzz: $t: /" || true
done
exit $status
