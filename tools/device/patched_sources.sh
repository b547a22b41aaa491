# Sourced by the probe builders (build_probes.sh, bvh_probe.sh, resident_probe.sh, timer_gaps_probe.sh): keeps
# copies of the sources a probe patches, puts them back on exit (also when a build fails) and
# rebuilds the normal binary.
#   keep_sources FILE...   save FILEs; restored when the script exits
#   reset_sources          put the saved FILEs back now (before patching the next variant)
kept_files=()
kept_dir=""
reset_sources() {
  local f
  for f in "${kept_files[@]}"; do cp "$kept_dir/$(basename "$f")" "$f"; done
}
restore_sources() {
  reset_sources
  rm -rf "$kept_dir"
  cmake --build --preset default > /dev/null
}
keep_sources() {
  kept_files=("$@")
  kept_dir=$(mktemp -d)
  local f
  for f in "${kept_files[@]}"; do cp "$f" "$kept_dir/$(basename "$f")"; done
  trap restore_sources EXIT
}
