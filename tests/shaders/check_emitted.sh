#!/usr/bin/env bash
# check_emitted.sh EXT SHADER_DIR COMMAND...: runs `COMMAND FILE` on every SHADER_DIR/*.EXT the
# shader tool emitted (*.spv: Vulkan's, not *.gl.spv); fails if there is none (shaders not built) or if any command fails.
set -u
ext="$1"; dir="$2"; shift 2
shopt -s nullglob
files=()
for f in "$dir"/*."$ext"; do
  # *.spv would also match OpenGL's *.gl.spv, which follows GL's rules, not Vulkan's.
  [[ "$ext" != gl.spv && "$f" == *.gl.spv ]] && continue
  files+=("$f")
done
if [ ${#files[@]} -eq 0 ]; then
  echo "check_emitted: no .$ext files in $dir; build the asvgf_shaders_generate target first" >&2
  exit 1
fi
failed=0
for f in "${files[@]}"; do
  if out="$("$@" "$f" 2>&1)"; then
    echo "ok: $(basename "$f")"
  else
    echo "FAILED: $(basename "$f"): $*"
    echo "$out"
    failed=1
  fi
done
exit $failed
