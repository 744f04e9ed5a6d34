#!/usr/bin/env bash
# Builds the libFuzzer targets for the plugin's config parser (plugin/fuzz/plugin_config_fuzz.cc)
# and the sweep-resume reader (studies/fuzz/sweep_resume_fuzz.cc) with AddressSanitizer and
# UndefinedBehaviorSanitizer, and runs each for a bounded time (the robot-log fuzzer is
# tools/fuzz_logs.sh).
#   usage: tools/fuzz_inputs.sh [SECONDS_EACH] [WORK_DIR]     (defaults: 60, build-fuzz)
# Exits non-zero when a fuzzer finds a crash, leak, timeout or undefined behaviour; the input is
# left in WORK_DIR/<target>/ (crash-*, leak-*, timeout-*).
# Needs: apt-get install -y clang nlohmann-json3-dev   (tools/setup.sh installs the latter)
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_TO_RUN="${1:-60}"
WORK="${2:-build-fuzz}"
CXX_FUZZ="${CXX_FUZZ:-$(command -v clang++ || command -v clang++-14 || true)}"
if [[ -z "$CXX_FUZZ" ]]; then
  echo "fuzz_inputs: clang++ not found (apt-get install -y clang)" >&2
  exit 2
fi
FLAGS=(-std=c++17 -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all -I.)
mkdir -p "$WORK/plugin_config/corpus" "$WORK/sweep_resume/corpus"
"$CXX_FUZZ" "${FLAGS[@]}" plugin/fuzz/plugin_config_fuzz.cc plugin/chamber_pressure_config.cc \
  plugin/pneumatics/cup_geometry.cc plugin/pneumatics/flow_network.cc \
  plugin/pneumatics/sensor_chain.cc common/strict_number.cc -o "$WORK/plugin_config_fuzz"
"$CXX_FUZZ" "${FLAGS[@]}" studies/fuzz/sweep_resume_fuzz.cc studies/sweep_io.cc common/output_file.cc \
  common/strict_number.cc -o "$WORK/sweep_resume_fuzz"

# Seeds.
printf 'noise_pa=6\nopening_radius_mm=5.5\nray_groups=0 2\nseed=3\n' > "$WORK/plugin_config/corpus/ok"
printf 'noise_pa=0x10\nrays_per_chamber=2.5\nlag_ms=1e400\n' > "$WORK/plugin_config/corpus/bad"
printf 'ray_groups=4\nlip_geom_group=4\naverage_samples=64\n' > "$WORK/plugin_config/corpus/groups"
H='scene,pref_pa,beta,step_mm,repeat,seed,outcome,s_mm,r_mean_mm,dr_mm,sigma_r_mm,s_c,duration_s,speed_mm_s,speed_body_d_s,contour_mean_mm,contour_max_mm,swept_deg,iterations,sim_time_s,detail'
R='gantry,100,2,7.5,0,11,success,209.7,32.6,-2.4,0.8,0.7,29.5,7.1,0.3,0.7,2.4,359.8,51,31.0,"swept, done"'
printf '%s\n%s\n%s' "$H" "$R" "${R:0:40}" > "$WORK/sweep_resume/corpus/torn"
printf '{"seed": "1", "scene": "gantry"}' > "$WORK/sweep_resume/corpus/manifest"

status=0
for t in plugin_config sweep_resume; do
  # -rss_limit_mb and -max_len keep a 2-core, shared machine usable; -timeout flags hangs.
  "$WORK/${t}_fuzz" -max_total_time="$SECONDS_TO_RUN" -print_final_stats=1 -max_len=4096 \
    -timeout=10 -rss_limit_mb=2048 -artifact_prefix="$WORK/$t/" "$WORK/$t/corpus" || status=1
done
exit $status
