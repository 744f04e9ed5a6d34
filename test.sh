#!/usr/bin/env bash
# Set everything up on a fresh machine and run the whole test suite (CTest + GoogleTest).
set -euo pipefail
cd "$(dirname "$0")"
tools/setup.sh
cd build
ctest --output-on-failure -j "${SSC_JOBS:-$(nproc)}" "$@"
