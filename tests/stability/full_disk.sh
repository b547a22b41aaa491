#!/usr/bin/env bash
# full_disk.sh ASVGF: renders into a 12 KiB tmpfs (a real full filesystem) and checks that the run
# fails with exit 1 naming a file and "No space left on device", and leaves every file under a final
# name whole and no temporary file. Needs root to mount; exits 77 (CTest's skip) where mount is not
# allowed.
set -u
asvgf="$1"
mnt="$(mktemp -d)"
if ! mount -t tmpfs -o size=12k tmpfs "$mnt" 2>/dev/null; then
  rmdir "$mnt"; echo "full_disk: cannot mount a tmpfs here (not root?): skipped"; exit 77
fi
trap 'umount "$mnt"; rmdir "$mnt"' EXIT
out="$("$asvgf" render --method raw --size 16x16 --frames 2 --reference-spp 4 --quiet --out "$mnt/out" 2>&1)"; rc=$?
echo "$out"
[ "$rc" = 1 ] || { echo "full_disk: FAIL: exit $rc, expected 1"; exit 1; }
grep -Eq "$mnt/out/[a-z_0-9]+\.(exr|png|csv): cannot write \((write|flush|sync|close)\): No space left on device" <<<"$out" ||
  { echo "full_disk: FAIL: no message names the file and the full disk"; exit 1; }
for f in "$mnt"/out/*; do
  case "$f" in
    *.partial) echo "full_disk: FAIL: $f left behind"; exit 1 ;;
    *.exr) [ "$(head -c 4 "$f" | od -An -tx1 | tr -d ' ')" = "762f3101" ] || { echo "full_disk: FAIL: $f is not whole"; exit 1; } ;;
    *.png) tail -c 12 "$f" | grep -q IEND || { echo "full_disk: FAIL: $f has no IEND chunk"; exit 1; } ;;
  esac
done
echo "full_disk: ok: exit 1 on a full filesystem, $(ls "$mnt/out" | wc -l) whole files, nothing half-written"
