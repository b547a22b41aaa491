#!/usr/bin/env bash
# concurrent_runs.sh ASVGF DIR: two `asvgf render --aovs` runs of different seeds into one folder at
# the same time, six times. The documented behaviour: each run writes through temporary names of
# its own, so every file in the folder is whole and byte for byte one run's (the last complete file
# wins), and nothing temporary is left. The two runs alone give the bytes to compare with. 96x96
# makes the writes long enough to overlap: the mutant with one temporary name for both runs failed
# 4 of 5 runs of this script (measured).
set -u
asvgf="$1"; dir="$2"
args=(render --method asvgf --size 96x96 --frames 3 --reference-spp 2 --aovs --quiet)
rm -rf "$dir"; mkdir -p "$dir"
"$asvgf" "${args[@]}" --seed 1 --out "$dir/alone1" || exit 1
"$asvgf" "${args[@]}" --seed 2 --out "$dir/alone2" || exit 1
cmp -s "$dir/alone1/frame_0001.exr" "$dir/alone2/frame_0001.exr" && { echo "concurrent: FAIL: the seeds give the same file"; exit 1; }
for attempt in 1 2 3 4 5 6; do
  both="$dir/both$attempt"
  "$asvgf" "${args[@]}" --seed 1 --out "$both" & a=$!
  "$asvgf" "${args[@]}" --seed 2 --out "$both" & b=$!
  wait $a || { echo "concurrent: FAIL: run of seed 1 failed"; exit 1; }
  wait $b || { echo "concurrent: FAIL: run of seed 2 failed"; exit 1; }
  for f in "$dir/alone1"/*; do
    name="$(basename "$f")"
    [ -f "$both/$name" ] || { echo "concurrent: FAIL: $both/$name missing"; exit 1; }
    same() {  # metrics.csv: its time columns differ between any two runs; compare frame, method, relMSE, SSIM
      if [[ "$name" == *.csv ]]; then diff -q <(cut -d, -f1-4 "$1") <(cut -d, -f1-4 "$2") >/dev/null; else cmp -s "$1" "$2"; fi
    }
    same "$both/$name" "$f" || same "$both/$name" "$dir/alone2/$name" ||
      { echo "concurrent: FAIL: $both/$name is neither run's file (a mixed file)"; exit 1; }
  done
  if ls "$both" | grep -q partial; then echo "concurrent: FAIL: temporary files left in $both"; exit 1; fi
done
echo "concurrent: ok: 6 x 2 runs into one folder, every file whole and one run's"
