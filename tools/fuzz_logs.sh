#!/usr/bin/env bash
# Builds the robot-log fuzz target (robotlog/fuzz/topic_csv_fuzz.cc) with clang's libFuzzer,
# AddressSanitizer and UndefinedBehaviorSanitizer, and runs it for a bounded time.
#   usage: tools/fuzz_logs.sh [SECONDS] [WORK_DIR]     (defaults: 60, build-fuzz)
# CTest runs it as a short smoke run (fuzz_logs_smoke: 5 s) when clang++ is installed; without
# clang it exits 77 and CTest reports a skip.
# Exits non-zero when the fuzzer finds a crash, leak, timeout or undefined behaviour; the input
# that did it is left in WORK_DIR (crash-*, leak-*, timeout-*) for the test suite.
# Needs: apt-get install -y clang libclang-rt-14-dev libmatio-dev libeigen3-dev
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_TO_RUN="${1:-60}"
WORK="${2:-build-fuzz}"
CXX_FUZZ="${CXX_FUZZ:-$(command -v clang++ || command -v clang++-14 || true)}"
if [[ -z "$CXX_FUZZ" ]]; then
  echo "fuzz_logs: clang++ not found (apt-get install -y clang libclang-rt-14-dev): skipped" >&2
  exit 77  # CTest's skip code
fi
mkdir -p "$WORK/corpus"
# Rebuilt only when a robotlog source is newer than the target (CTest runs this often).
if [[ ! -x "$WORK/topic_csv_fuzz" ]] || \
   [[ -n "$(find robotlog -name '*.cc' -newer "$WORK/topic_csv_fuzz" -o -name '*.h' -newer "$WORK/topic_csv_fuzz")" ]]; then
  "$CXX_FUZZ" -std=c++17 -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all \
  -I. -I/usr/include/eigen3 robotlog/fuzz/topic_csv_fuzz.cc robotlog/align.cc \
  robotlog/mat_log.cc robotlog/plain_log.cc robotlog/robot_log.cc robotlog/synthetic_log.cc \
  robotlog/text_cells.cc robotlog/topic_csv.cc common/output_file.cc -lmatio -o "$WORK/topic_csv_fuzz"
fi

# Seeds: the lab's topic files (both logger versions) and a plain log.
printf '%s\n%s\n%s\n' \
  'ROStimestamp,/SensorPacket.ch,/SensorPacket.data[0],/SensorPacket.data[1],/SensorPacket.data[2],/SensorPacket.data[3]' \
  '1700000000000000000,4,101000.5, 101010.25, 101020.0, 101030.0' \
  '1700000000010000000,4,100000.0, 100010.0, 100020.0, 100030.0' > "$WORK/corpus/seed_pressure"
printf '%s\n%s\n' 'ROStimestamp,/SensorPacket.data,/SensorPacket.data,/SensorPacket.data,/SensorPacket.data' \
  '1700000000000000000,101000.5, 101010.25, 101020.0, 101030.0' > "$WORK/corpus/seed_pressure_older"
printf '%s\n%s\n' 'ROStimestamp,/endEffectorPose.pose.orientation.w,/endEffectorPose.pose.orientation.x,/endEffectorPose.pose.orientation.y,/endEffectorPose.pose.orientation.z,/endEffectorPose.pose.position.x,/endEffectorPose.pose.position.y,/endEffectorPose.pose.position.z' \
  '1700000000000000000,0.0,0.7071,-0.7071,0.0,-0.63,0.097,0.161' > "$WORK/corpus/seed_pose"
printf 'ROStimestamp,/pwm.data\n1700000000000000000,100\n' > "$WORK/corpus/seed_pwm"
printf '%s\n%s\n' 't_s,x_m,y_m,z_m,qw,qx,qy,qz,p1_pa,p2_pa,p3_pa,p4_pa,pwm_pct' \
  '0,0.1,0.2,0.3,1,0,0,0,10,20,30,40,100' > "$WORK/corpus/seed_plain"

# -rss_limit_mb and -max_len keep a 2-core, shared machine usable; -timeout flags hangs.
"$WORK/topic_csv_fuzz" -max_total_time="$SECONDS_TO_RUN" -print_final_stats=1 \
  -max_len=4096 -timeout=10 -rss_limit_mb=2048 -artifact_prefix="$WORK/" "$WORK/corpus"
