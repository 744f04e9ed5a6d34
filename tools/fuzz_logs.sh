#!/usr/bin/env bash
# Builds the robot-log fuzz target (robotlog/fuzz/topic_csv_fuzz.cc) with clang's libFuzzer,
# AddressSanitizer and UndefinedBehaviorSanitizer, and runs it for a bounded time.
#   usage: tools/fuzz_logs.sh [SECONDS] [WORK_DIR]     (defaults: 60, build-fuzz)
# Exits non-zero when the fuzzer finds a crash, leak, timeout or undefined behaviour; the input
# that did it is left in WORK_DIR (crash-*, leak-*, timeout-*) for the test suite.
# Needs: apt-get install -y clang libclang-rt-14-dev libmatio-dev libeigen3-dev
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_TO_RUN="${1:-60}"
WORK="${2:-build-fuzz}"
CXX_FUZZ="${CXX_FUZZ:-$(command -v clang++ || command -v clang++-14 || true)}"
if [[ -z "$CXX_FUZZ" ]]; then
  echo "fuzz_logs: clang++ not found (apt-get install -y clang libclang-rt-14-dev)" >&2
  exit 2
fi
mkdir -p "$WORK/corpus"
"$CXX_FUZZ" -std=c++17 -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all \
  -I. -I/usr/include/eigen3 robotlog/fuzz/topic_csv_fuzz.cc robotlog/align.cc \
  robotlog/mat_log.cc robotlog/plain_log.cc robotlog/robot_log.cc robotlog/synthetic_log.cc \
  robotlog/text_cells.cc robotlog/topic_csv.cc -lmatio -o "$WORK/topic_csv_fuzz"

# Seeds: the first byte picks the topic (0 pressure, 1 pose, 2 F/T, 3 PWM).
printf '\x00t_ns,ch,P1,P2,P3,P4\n%s\n%s\n' '1000000000,1,101000,101010,101020,101030' \
  '1010000000,1,100000,100010,100020,100030' > "$WORK/corpus/seed_pressure"
printf '\x011,1,0,0,0,0.5,0.1,0.3\n2,0.7071,0.7071,0,0,0.5,0.1,0.3\n' > "$WORK/corpus/seed_pose"
printf '\x02%s\r\n5,0.1,-2e-1,1.5,0,0,nan\r\n' \
  '%time,field.force.x,field.force.y,field.force.z,field.torque.x,field.torque.y,field.torque.z' \
  > "$WORK/corpus/seed_ft"
printf '\x03stamp,data\n1,255\n2,128\n' > "$WORK/corpus/seed_pwm"
printf '\x00%s\n%s\n' 't_s,x_m,y_m,z_m,qw,qx,qy,qz,p1_pa,p2_pa,p3_pa,p4_pa,pwm_pct' \
  '0,0.1,0.2,0.3,1,0,0,0,10,20,30,40,100' > "$WORK/corpus/seed_plain"

# -rss_limit_mb and -max_len keep a 2-core, shared machine usable; -timeout flags hangs.
"$WORK/topic_csv_fuzz" -max_total_time="$SECONDS_TO_RUN" -print_final_stats=1 \
  -max_len=4096 -timeout=10 -rss_limit_mb=2048 -artifact_prefix="$WORK/" "$WORK/corpus"
