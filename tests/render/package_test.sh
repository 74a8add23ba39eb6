#!/usr/bin/env bash
# The .deb on a newcomer's machine (ctest label `package`, slow: run with SOFTBODY_PACKAGE_TEST=1): builds the
# package with CPack, installs it with apt-get into a fresh Debian 12 root (debootstrap minbase, kept as a
# pristine tarball in the build tree after the first run and unpacked anew every time), and renders the
# bounce from PATH in the home folder, with EGL and with OSMesa, and from the Python module. Exit 77 (ctest: skipped) when not asked
# for, not root, or debootstrap cannot reach the Debian archive.
#   package_test.sh BUILD_DIR SCRATCH_DIR
set -euo pipefail
build=$1; scratch=$2
if [ "${SOFTBODY_PACKAGE_TEST:-}" != 1 ]; then
  echo "SKIP: slow (a Debian root and its packages); run: SOFTBODY_PACKAGE_TEST=1 ctest -L package"; exit 77
fi
[ "$(id -u)" -eq 0 ] || { echo "SKIP: needs root (debootstrap, chroot)"; exit 77; }
if ! command -v debootstrap >/dev/null; then
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq debootstrap >/dev/null 2>&1 ||
    { echo "SKIP: debootstrap is missing and could not be installed"; exit 77; }
fi

root="$scratch/root"
cleanup() {
  mountpoint -q "$root/proc" && umount "$root/proc"
  rm -rf "$root"
}
trap cleanup EXIT
cleanup
mkdir -p "$scratch"

started=$(date +%s)
rm -f "$scratch"/softbody_*.deb
cpack --config "$build/CPackConfig.cmake" -B "$scratch" >"$scratch/cpack.log" 2>&1 ||
  { cat "$scratch/cpack.log"; echo "FAIL: cpack"; exit 1; }
deb=$(ls "$scratch"/softbody_*.deb)
echo "package: $(basename "$deb"), $(du -k "$deb" | cut -f1) kB"
echo "Depends: $(dpkg-deb -f "$deb" Depends)"

pristine="$build/package_test_debian12_minbase.tar"
if [ ! -f "$pristine" ]; then
  debootstrap_started=$(date +%s)
  debootstrap --variant=minbase bookworm "$root" http://deb.debian.org/debian >"$scratch/debootstrap.log" 2>&1 ||
    { tail -5 "$scratch/debootstrap.log"; echo "SKIP: debootstrap failed (is deb.debian.org reachable?)"; exit 77; }
  tar -C "$root" -cf "$pristine.tmp" . && mv "$pristine.tmp" "$pristine"
  echo "debootstrap --variant=minbase bookworm: $(( $(date +%s) - debootstrap_started )) s (kept in $pristine)"
else
  mkdir -p "$root" && tar -C "$root" -xf "$pristine"
fi
cp /etc/resolv.conf "$root/etc/resolv.conf"
mount -t proc proc "$root/proc"
cp "$deb" "$root/tmp/"

in_root() { chroot "$root" /usr/bin/env -i PATH=/usr/local/bin:/usr/bin:/bin HOME=/root "$@"; }
install_started=$(date +%s)
in_root apt-get update -qq >"$scratch/apt.log" 2>&1
in_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "/tmp/$(basename "$deb")" \
  >>"$scratch/apt.log" 2>&1 || { tail -20 "$scratch/apt.log"; echo "FAIL: apt-get could not install the .deb"; exit 1; }
echo "apt-get install of the .deb and its dependencies: $(( $(date +%s) - install_started )) s"

status=0
for backend in egl osmesa; do
  out=$(in_root sh -c "mkdir -p /root/work && cd /root/work && command -v softbody && softbody --version &&
        SOFTBODY_GL=$backend softbody render /usr/share/softbody/scenes/bounce.json --set duration=0.5 \
        --set render.width=320 --set render.height=180 -o bounce_$backend" 2>&1) || status=$?
  echo "$out" | sed "s/^/  [$backend] /"
  [ $status -eq 0 ] || { echo "FAIL: softbody render ($backend) in the fresh root exited $status"; exit 1; }
  frames=$(ls "$root/root/work/bounce_$backend"/frame_*.png | wc -l)
  [ "$frames" -eq 16 ] || { echo "FAIL: $frames frames ($backend), expected 16"; exit 1; }
  [ -s "$root/root/work/bounce_$backend/figure.png" ] || { echo "FAIL: no figure.png ($backend)"; exit 1; }
  echo "$out" | grep -q "backend $backend" || { echo "FAIL: the summary does not name $backend"; exit 1; }
done
# The Python module, where the build makes one: the system's python3 imports it and renders a frame.
if compgen -G "$build/python/softbody*.so" >/dev/null; then
  out=$(in_root python3 -c "import softbody
sim = softbody.Simulation(softbody.load_scene('/usr/share/softbody/scenes/bounce.json', set={'duration': 0.1}))
frames = [frame.index for frame in sim.frames()]
image = softbody.render(sim, width=64, height=48)
print('softbody', softbody.__version__, frames, image.shape, image.dtype)" 2>&1) || { echo "$out"; echo "FAIL: import softbody"; exit 1; }
  echo "  [python] $out"
  echo "$out" | grep -q "\[0, 1, 2, 3\] (48, 64, 3) uint8" || { echo "FAIL: the Python module's frames or image"; exit 1; }
fi
[ -f "$root/usr/share/man/man1/softbody.1.gz" ] || { echo "FAIL: no man page installed"; exit 1; }
[ -f "$root/usr/share/softbody/scenes/meshes/pillow.obj" ] || { echo "FAIL: the scenes' meshes are not installed"; exit 1; }
grep -q "^License: GPL-3.0-or-later" "$root/usr/share/doc/softbody/copyright" ||
  { echo "FAIL: no copyright file naming GPL-3.0-or-later in /usr/share/doc/softbody"; exit 1; }
echo "package test: OK in $(( $(date +%s) - started )) s"
