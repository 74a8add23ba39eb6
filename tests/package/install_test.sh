#!/usr/bin/env bash
# `cmake --install` into a scratch prefix: the program, its scenes and man page, and the licence files a user
# and Debian's policy expect (LICENSE, THIRD_PARTY_NOTICES.md and the copyright file in share/doc/softbody/);
# the installed program's --version names the licence; the Python module where the build makes one.
#   install_test.sh BUILD_DIR SCRATCH_DIR
set -euo pipefail
build=$1; prefix=$2/install
rm -rf "$prefix"
cmake --install "$build" --prefix "$prefix" >/dev/null
status=0
for f in bin/softbody share/softbody/scenes/bounce.json share/softbody/scenes/gallery/spot.obj \
         share/man/man1/softbody.1.gz share/doc/softbody/README.md share/doc/softbody/LICENSE \
         share/doc/softbody/THIRD_PARTY_NOTICES.md share/doc/softbody/copyright; do
  [ -s "$prefix/$f" ] || { echo "FAIL: $f not installed"; status=1; }
done
grep -q "GNU GENERAL PUBLIC LICENSE" "$prefix/share/doc/softbody/LICENSE" || { echo "FAIL: LICENSE is not the GPL"; status=1; }
grep -q "^License: GPL-3.0-or-later" "$prefix/share/doc/softbody/copyright" ||
  { echo "FAIL: the copyright file does not name GPL-3.0-or-later"; status=1; }
# The Python module, where the build has one: in PREFIX/lib/python3.X/dist-packages, and it imports from there.
if compgen -G "$build/python/softbody*.so" >/dev/null; then
  module=$(compgen -G "$prefix/lib/python3*/dist-packages/softbody*.so" | head -n 1 || true)
  python=$(sed -n 's/^Python3_EXECUTABLE:[A-Z]*=//p' "$build/CMakeCache.txt")
  if [ -z "$module" ]; then
    echo "FAIL: the Python module is not installed in lib/python3.X/dist-packages"; status=1
  elif ! (cd / && PYTHONPATH=$(dirname "$module") "${python:-python3}" -c "import softbody; print('softbody', softbody.__version__)"); then
    echo "FAIL: the installed Python module does not import"; status=1
  fi
fi
version=$("$prefix/bin/softbody" --version)
echo "$version"
echo "$version" | grep -q "GPL-3.0-or-later" || { echo "FAIL: --version does not name the licence"; status=1; }
[ $status -eq 0 ] && echo "install test: OK"
exit $status
