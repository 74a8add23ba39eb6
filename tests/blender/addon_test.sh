#!/usr/bin/env bash
# The Blender add-on against the real Blender and the real program (ctest label `blender`): installs
# build/blender/softbody_blender.zip into a headless Blender, bakes, and compares with the program's own export
# (tests/blender/addon_check.py says what is checked). Installs Debian's blender where it is missing and this runs
# as root; exit 77 (ctest: skipped) with a line saying why where Blender cannot be installed or cannot run headless.
#   addon_test.sh SOFTBODY ADDON_ZIP SOURCE_DIR SCRATCH_DIR
set -euo pipefail
softbody=$1; zip=$2; source_dir=$3; scratch=$4
rm -rf "$scratch"; mkdir -p "$scratch"

source "$source_dir/tests/blender/ensure_blender.sh"

# The add-on is installed into a scratch user folder, never into the user's own Blender.
BLENDER_USER_SCRIPTS="$scratch/user_scripts" \
  blender -b --factory-startup --python-exit-code 1 --python "$source_dir/tests/blender/addon_check.py" -- \
  "$zip" "$softbody" "$scratch" >"$scratch/blender.log" 2>&1 ||
  { cat "$scratch/blender.log"; echo "FAIL: the add-on check failed"; exit 1; }
grep -E "^blender|FAIL" "$scratch/blender.log"
