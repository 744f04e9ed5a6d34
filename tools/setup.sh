#!/usr/bin/env bash
# Install everything the project needs on a fresh Debian/Ubuntu machine and build it.
#   - Debian packages: compiler, CMake, Eigen, GLFW, tinyxml2, GoogleTest, Xvfb + Mesa (for
#     off-screen screenshots), matio (robot .mat logs), nlohmann-json (reports), CLI11 (command line), python3-venv, Open MPI (studies under
#     mpirun; optional at build time).
#   - .venv/ with the MuJoCo wheel pinned in requirements.txt (plus matplotlib for plots).
#   - The code checks' tools (tools/check_code.sh): clang-format and cppcheck (Debian), lizard
#     (PyPI, requirements.txt).
#   - CMake configure + build into build/ (executables in build/bin/).
#   tools/setup.sh --deps-only    the packages and .venv only, no build
# Safe to re-run: each step is skipped when already done.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT="$(pwd)"

APT_PACKAGES=(build-essential cmake pkg-config python3 python3-venv python3-pip
  nlohmann-json3-dev libnlopt-dev libnlopt-cxx-dev
  libeigen3-dev libglfw3-dev libtinyxml2-dev libgtest-dev libgmock-dev libmatio-dev
  libstb-dev libcli11-dev nlohmann-json3-dev xvfb xauth libgl1-mesa-dri libglx-mesa0 libgl1-mesa-dev
  libegl1 libegl-mesa0
  libopenmpi-dev openmpi-bin clang-format cppcheck)

missing=()
for p in "${APT_PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "[setup] installing Debian packages: ${missing[*]}"
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

PY=python3
if [ ! -x .venv/bin/python ]; then
  echo "[setup] creating .venv"
  $PY -m venv .venv
fi
if ! .venv/bin/python -m pip install -q --disable-pip-version-check -r requirements.txt; then
  echo "[setup] ERROR: could not install the pinned Python packages (requirements.txt)." >&2
  echo "[setup] The MuJoCo wheel is required; this project does not fall back to Debian's" >&2
  echo "[setup] libmujoco-dev 2.2.2, which predates the plugin API." >&2
  exit 1
fi

if [ "${1:-}" = "--deps-only" ]; then exit 0; fi

BUILD_DIR="${SSC_BUILD_DIR:-build}"
JOBS="${SSC_JOBS:-$(nproc)}"
# SSC_WERROR=ON (set by .ci/run): the project's compiler warnings become errors.
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release -DSSC_PYTHON="$ROOT/.venv/bin/python" \
  -DSSC_BUILD_PYTHON=ON -DPython_EXECUTABLE="$ROOT/.venv/bin/python" \
  -DSSC_WERROR="${SSC_WERROR:-OFF}" >/dev/null
cmake --build "$BUILD_DIR" -j "$JOBS"
echo "[setup] built into $BUILD_DIR/bin"
