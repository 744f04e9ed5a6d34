#!/usr/bin/env bash
# cmake --install into a temporary prefix; a downstream project finds it with find_package(ssc),
# links, installs into the same prefix and finds the scenes there (not in the source tree); the
# installed `ssc` runs a trial there without writing MUJOCO_LOG.TXT.
#   install_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build="$1"; src="$2"
tmp="$(mktemp -d /tmp/ssc_install_XXXXXX)"
trap 'rm -rf "$tmp"' EXIT
prefix="$tmp/prefix"
cmake --install "$build" --prefix "$prefix" >/dev/null
for f in bin/ssc lib/libssc_plugin.so include/ssc/plugin/chamber_pressure_sensor.h \
         share/ssc/models/ssc_tool.xml share/ssc/scenes/disk_benchmark.xml \
         share/ssc/data/published/success_map_dl5.csv \
         lib/cmake/ssc/sscConfig.cmake; do
  [ -e "$prefix/$f" ] || { echo "FAIL: $f not installed"; exit 1; }
done
cmake -S "$src/tests/install/downstream" -B "$tmp/build" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_INSTALL_PREFIX="$prefix" -DCMAKE_BUILD_TYPE=Release >"$tmp/configure.log" 2>&1 ||
  { cat "$tmp/configure.log"; exit 1; }
cmake --build "$tmp/build" -j2 >"$tmp/build.log" 2>&1 || { cat "$tmp/build.log"; exit 1; }
cmake --install "$tmp/build" >/dev/null
cd "$tmp"
env -u SSC_SOURCE_DIR -u SSC_RESOURCE_DIR "$prefix/bin/ssc_downstream" | tee out.txt
grep -qx "resources $prefix/share/ssc" out.txt || { echo "FAIL: not the installed resources"; exit 1; }
grep -q "phase approach\|phase move\|phase follow" out.txt || { echo "FAIL: no trial"; exit 1; }
env -u SSC_SOURCE_DIR -u SSC_RESOURCE_DIR "$prefix/bin/ssc" trial --stop-at 0.3 --no-plot --out "$tmp/t"
[ ! -e "$tmp/MUJOCO_LOG.TXT" ] || { echo "FAIL: MUJOCO_LOG.TXT written"; exit 1; }
echo "install test passed"
