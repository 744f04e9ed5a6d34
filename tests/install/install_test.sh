#!/usr/bin/env bash
# cmake --install into a temporary prefix; a downstream project finds it with find_package(ssc),
# links, finds the prefix's scenes (not the source tree's) both from its build folder and once
# installed into the same prefix; the installed `ssc` runs a trial there without writing
# MUJOCO_LOG.TXT.
#   install_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build="$1"; src="$2"
tmp="$(mktemp -d /tmp/ssc_install_XXXXXX)"
trap 'rm -rf "$tmp"' EXIT
prefix="$tmp/prefix"
cmake --install "$build" --prefix "$prefix" >/dev/null
for f in bin/ssc bin/ssc_bench lib/libssc_plugin.so include/ssc/plugin/chamber_pressure_sensor.h \
         share/ssc/models/ssc_tool.xml share/ssc/scenes/disk_benchmark.xml \
         share/ssc/data/published/success_map_dl5.csv \
         lib/cmake/ssc/sscConfig.cmake; do
  [ -e "$prefix/$f" ] || { echo "FAIL: $f not installed"; exit 1; }
done
cmake -S "$src/tests/install/downstream" -B "$tmp/build" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_INSTALL_PREFIX="$prefix" -DCMAKE_BUILD_TYPE=Release >"$tmp/configure.log" 2>&1 ||
  { cat "$tmp/configure.log"; exit 1; }
cmake --build "$tmp/build" -j2 >"$tmp/build.log" 2>&1 || { cat "$tmp/build.log"; exit 1; }
cd "$tmp"
# Not yet installed, run from its build folder: the scenes of the prefix it was built against
# (found from the plugin library it loaded), not the builder's source tree.
env -u SSC_SOURCE_DIR -u SSC_RESOURCE_DIR "$tmp/build/ssc_downstream" | tee uninstalled.txt
grep -qx "resources $prefix/share/ssc" uninstalled.txt ||
  { echo "FAIL: the uninstalled downstream does not use the prefix's resources"; exit 1; }
cmake --install "$tmp/build" >/dev/null
env -u SSC_SOURCE_DIR -u SSC_RESOURCE_DIR "$prefix/bin/ssc_downstream" | tee out.txt
grep -qx "resources $prefix/share/ssc" out.txt || { echo "FAIL: not the installed resources"; exit 1; }
grep -q "phase approach\|phase move\|phase follow" out.txt || { echo "FAIL: no trial"; exit 1; }
env -u SSC_SOURCE_DIR -u SSC_RESOURCE_DIR "$prefix/bin/ssc" trial --stop-at 0.3 --no-plot --out "$tmp/t"
[ ! -e "$tmp/MUJOCO_LOG.TXT" ] || { echo "FAIL: MUJOCO_LOG.TXT written"; exit 1; }
# Everything `ssc` runs is installed: `ssc bench` finds its binary next to the installed `ssc`.
env -u SSC_SOURCE_DIR -u SSC_RESOURCE_DIR "$prefix/bin/ssc" bench --help >/dev/null ||
  { echo "FAIL: the installed ssc bench does not run"; exit 1; }
# The prefix moved elsewhere (the original removed): nothing in it points into the builder's
# venv, build or source tree; `ssc` runs from the copy with the copy's libmujoco and scenes; a
# project that needs only the control law configures without MuJoCo, NLopt, nlohmann-json, MPI.
moved="$tmp/moved/elsewhere"
mkdir -p "$(dirname "$moved")"
cp -a "$prefix" "$moved"
rm -rf "$prefix" "$tmp/build"
venv="$(cd "$src" && pwd)/.venv"
for f in "$moved"/bin/ssc "$moved"/lib/*.so*; do
  rp="$(readelf -d "$f" | sed -n 's/.*R\(UN\)\?PATH.*\[\(.*\)\]/\2/p')"
  for part in ${rp//:/ }; do
    case "$part" in '$ORIGIN'*|'') ;; *) echo "FAIL: $f has the absolute rpath $part"; exit 1 ;; esac
  done
done
if grep -rl -e "$venv" -e "$build" -e "$src" "$moved/lib/cmake/ssc"; then
  echo "FAIL: the package config names the builder's tree"; exit 1
fi
# ldd's whole output first: grep -q closing the pipe early fails the pipeline under pipefail.
libs=$(ldd "$moved/bin/ssc")
grep -q "libmujoco.* => $moved/bin/../lib/" <<<"$libs" ||
  { echo "$libs"; echo "FAIL: libmujoco not from the prefix"; exit 1; }
env -u SSC_SOURCE_DIR -u SSC_RESOURCE_DIR "$moved/bin/ssc" trial --stop-at 0.3 --no-plot \
  --out "$tmp/moved_trial" >/dev/null
cmake -S "$src/tests/install/downstream_control" -B "$tmp/control" \
  -DCMAKE_PREFIX_PATH="$moved" -DCMAKE_BUILD_TYPE=Release >"$tmp/control.log" 2>&1 ||
  { cat "$tmp/control.log"; exit 1; }
cmake --build "$tmp/control" >"$tmp/control_build.log" 2>&1 || { cat "$tmp/control_build.log"; exit 1; }
"$tmp/control/control_law" | grep -q "^step " || { echo "FAIL: control law"; exit 1; }
echo "install test passed"
