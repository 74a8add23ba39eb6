#!/usr/bin/env bash
# The Blender add-on against the real Blender and the real program (ctest label `blender`): installs
# build/blender/softbody_blender.zip into a headless Blender, bakes, and compares with the program's own export
# (tests/blender/addon_check.py says what is checked). Installs Debian's blender where it is missing and this runs
# as root; exit 77 (ctest: skipped) with a line saying why where Blender cannot be installed or cannot run headless.
#   addon_test.sh SOFTBODY ADDON_ZIP SOURCE_DIR SCRATCH_DIR
set -euo pipefail
softbody=$1; zip=$2; source_dir=$3; scratch=$4
rm -rf "$scratch"; mkdir -p "$scratch"

if ! command -v blender >/dev/null; then
  if [ "$(id -u)" -eq 0 ] && command -v apt-get >/dev/null; then
    echo "installing blender (Debian package, about 300 MB with its libraries)"
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends blender >/dev/null 2>&1 ||
      { apt-get update -qq >/dev/null 2>&1 &&
        DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends blender >/dev/null 2>&1; } ||
      { echo "SKIP: blender is not installed and apt-get could not install it"; exit 77; }
  else
    echo "SKIP: blender is not installed (apt-get install blender, as root, to run this test)"; exit 77
  fi
fi
if ! blender -b --factory-startup --python-exit-code 1 --python-expr "import bpy" >"$scratch/probe.log" 2>&1; then
  echo "SKIP: blender cannot run headless here:"; tail -5 "$scratch/probe.log"; exit 77
fi

# The add-on is installed into a scratch user folder, never into the user's own Blender.
BLENDER_USER_SCRIPTS="$scratch/user_scripts" \
  blender -b --factory-startup --python-exit-code 1 --python "$source_dir/tests/blender/addon_check.py" -- \
  "$zip" "$softbody" "$scratch" >"$scratch/blender.log" 2>&1 ||
  { cat "$scratch/blender.log"; echo "FAIL: the add-on check failed"; exit 1; }
grep -E "^blender|FAIL" "$scratch/blender.log"
