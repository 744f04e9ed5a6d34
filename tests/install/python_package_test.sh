#!/usr/bin/env bash
# pip builds the ssc_twin wheel (scikit-build-core + nanobind; a persistent build folder under
# BUILD_DIR makes re-runs incremental), installs it into a temporary venv and runs
# python/tests/package_test.py there against the CLI, then strict_args_test.py (bad arguments).
#   python_package_test.sh SOURCE_DIR BUILD_DIR PYTHON SSC
# The temporary venv borrows the project venv's mujoco, numpy and gymnasium (a .pth file), so no
# download is needed. Exit 77 (CTest: skipped) when the build tools are missing.
set -euo pipefail
src="$1"; build="$2"; py="$3"; ssc="$4"
if ! "$py" -c "import scikit_build_core, nanobind, gymnasium" 2>/dev/null; then
  echo "SKIP: scikit-build-core, nanobind or gymnasium missing in $py (tools/setup.sh installs them)"
  exit 77
fi
wheels="$build/python/wheels"
rm -f "$wheels"/ssc_twin-*.whl
"$py" -m pip wheel "$src" --no-build-isolation --no-deps --disable-pip-version-check -q \
  -w "$wheels" -C build-dir="$build/python/wheel-build" -C cmake.define.SSC_PYTHON="$py"
tmp="$(mktemp -d /tmp/ssc_pkg_venv_XXXXXX)"
trap 'rm -rf "$tmp"' EXIT
"$py" -m venv "$tmp/venv"
deps="$("$py" -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')"
site="$("$tmp/venv/bin/python" -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')"
echo "$deps" > "$site/ssc_project_deps.pth"
"$tmp/venv/bin/python" -m pip install --no-deps --no-index --disable-pip-version-check -q \
  "$wheels"/ssc_twin-*.whl
cd "$tmp"
env -u SSC_SOURCE_DIR -u SSC_RESOURCE_DIR -u PYTHONPATH \
  "$tmp/venv/bin/python" "$src/python/tests/package_test.py" "$ssc"
env -u SSC_SOURCE_DIR -u SSC_RESOURCE_DIR -u PYTHONPATH \
  "$tmp/venv/bin/python" "$src/python/tests/strict_args_test.py"
