# Sourced by the tests that run the real Blender (ctest label `blender`): installs Debian's blender where it is
# missing and this runs as root, and exits 77 (ctest: skipped) with a line saying why where Blender cannot be
# installed or cannot run headless. Needs $scratch, a folder for the probe's log.
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
