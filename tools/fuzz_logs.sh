#!/usr/bin/env bash
# Builds the robot-log CSV fuzz target with clang's libFuzzer (+ASan/UBSan) and runs it for a
# bounded time. usage: tools/fuzz_logs.sh [SECONDS]   (default 60)
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_TO_RUN="${1:-60}"
command -v clang++ >/dev/null || { echo "fuzz: clang++ not installed (apt-get install clang libclang-rt-14-dev)" >&2; exit 2; }
mkdir -p build-fuzz/corpus
clang++ -std=c++17 -g -O1 -fsanitize=fuzzer,address,undefined -I. \
  robotlog/fuzz/topic_csv_fuzz.cc robotlog/robot_log.cc -o build-fuzz/robotlog_fuzz
printf 't_ns,ch,P1,P2,P3,P4\n1,1,100000,100100,100200,100300\n2,1,100000,100100,100200,100300\n' \
  > build-fuzz/corpus/seed.csv
build-fuzz/robotlog_fuzz -max_total_time="$SECONDS_TO_RUN" -print_final_stats=1 build-fuzz/corpus
