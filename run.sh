#!/usr/bin/env bash
# Set everything up on a fresh machine and run the main job.
set -euo pipefail
cd "$(dirname "$0")"
tools/setup.sh
mkdir -p out
build/bin/ssc probe --out out/probe "$@"
