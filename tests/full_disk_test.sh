#!/usr/bin/env bash
# A full disk: simulate and export into a 256 kB tmpfs (mounted here; skipped, exit 77, where mounting is not
# allowed). Each must exit 1 with one message naming the file, leave no temporary, and leave only complete
# files: no CSV at all (it is written whole), and every mesh frame that is there whole.
#   full_disk_test.sh SOFTBODY SOURCE_DIR SCRATCH_DIR
set -uo pipefail
softbody=$1; source_dir=$2; scratch=$3
mnt=$scratch/full_disk
mkdir -p "$mnt"
mount -t tmpfs -o size=256k tmpfs "$mnt" 2>/dev/null || { echo "cannot mount a tmpfs here: skipped"; exit 77; }
trap 'umount "$mnt"' EXIT
cd "$source_dir"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# The CSV of 3000 frames (~700 kB) does not fit.
"$softbody" simulate scenes/bounce.json --set duration=100 --set bodies.0.mesh=icosphere:1 --csv "$mnt/sim.csv" \
  >"$scratch/simulate.out" 2>&1
status=$?
[ $status -eq 1 ] || fail "simulate on a full disk: exit $status, expected 1"
grep -q "^error: $mnt/sim.csv: write failed" "$scratch/simulate.out" || fail "simulate: message: $(cat "$scratch/simulate.out")"
[ ! -e "$mnt/sim.csv" ] || fail "simulate left a CSV on a full disk"
[ -z "$(ls -A "$mnt")" ] || fail "simulate left: $(ls -A "$mnt")"

# 301 mesh frames of ~3 kB: the disk fills part way.
"$softbody" export scenes/bounce.json --set duration=10 --set bodies.0.mesh=icosphere:1 -o "$mnt/meshes" \
  >"$scratch/export.out" 2>&1
status=$?
[ $status -eq 1 ] || fail "export on a full disk: exit $status, expected 1"
grep -q "^error: $mnt/meshes/frame_[0-9]*.obj: write failed" "$scratch/export.out" || fail "export: message: $(cat "$scratch/export.out")"
frames=$(ls "$mnt/meshes" | grep -c '^frame_' || true)
[ "$frames" -gt 0 ] || fail "export wrote no frame before the disk was full"
for f in "$mnt"/meshes/frame_*.obj; do
  [ "$(tail -c 1 "$f" | od -An -c | tr -d ' ')" = '\n' ] || fail "$f is cut short"
  grep -q '^f ' "$f" || fail "$f has no faces"
done
temporaries=$(ls -A "$mnt/meshes" | grep '^\.' || true)
[ -z "$temporaries" ] || fail "export left temporaries: $temporaries"
echo "full disk: simulate exit 1 and no CSV; export exit 1 after $frames complete frames, no temporary"
exit $failures
