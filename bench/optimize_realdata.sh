#!/usr/bin/env bash
# Whole-program re-optimisation on real programs written by others (../shared/realdata, or
# ISURFACE_SHARED_DIR/realdata): `optimize --all`, both simulations and every candidate the
# closed loop tries included, as one process timed by /usr/bin/time -v (Debian package `time`).
# Bound: cameo.nc (196 min of machining, 11.8 M samples) in 120 s of wall time. For each program
# it prints the wall time, the peak resident set size, whether the candidate was kept, the
# machining time and the whole program's figures before and after (from the report).
# It exits 1 when a run fails or cameo.nc exceeds its bound.
# With --every-mode it runs instead the never-worse property test (tests/cli/
# region_optimizer_cli_test.cpp) on cameo.nc and stellabee1.ngc in every mode and objective,
# the part CI leaves out (about 13 minutes here).
# Usage: bench/optimize_realdata.sh [BUILD_DIR [PROGRAM...]]   (default: build, cameo.nc)
#        bench/optimize_realdata.sh --every-mode [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" = --every-mode ]; then
  exec "${2:-build}/bin/cli_tests" --gtest_also_run_disabled_tests \
    --gtest_filter='regionOptimizer.*LongRealProgram:regionOptimizerLong.NoModeWritesAWorseCameo*:regionOptimizerLong.NoModeWritesAWorseStellabee'
fi
build=${1:-build}
shift || true
cli="$build/bin/isurface-cli"
realdata=${ISURFACE_SHARED_DIR:-../shared}/realdata
[ -x "$cli" ] || { echo "optimize_realdata: $cli is missing (build first)" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "optimize_realdata: /usr/bin/time is missing (apt-get install time)" >&2; exit 1; }
programs=("$@")
[ ${#programs[@]} -gt 0 ] || programs=("$realdata/cameo.nc")
work=$(mktemp -d /tmp/isurface-optimize.XXXXXX)
trap 'rm -rf "$work"' EXIT

status=0
for program in "${programs[@]}"; do
  name=$(basename "$program")
  if ! /usr/bin/time -v "$cli" optimize "$program" --all -o "$work/$name" --report "$work/$name.json" \
      >"$work/out" 2>"$work/time"; then
    echo "optimize_realdata: $name failed:" >&2
    cat "$work/time" >&2
    status=1
    continue
  fi
  wall=$(awk -F': ' '/Elapsed \(wall clock\)/ {n = split($2, t, ":"); s = 0; for (i = 1; i <= n; i++) s = s * 60 + t[i]; print s}' "$work/time")
  peak=$(awk -F': ' '/Maximum resident set size/ {printf "%.0f", $2 / 1024}' "$work/time")
  python3 - "$work/$name.json" "$name" "$wall" "$peak" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
name, wall, peak = sys.argv[2], float(sys.argv[3]), sys.argv[4]
t = r["machining_time_s"]
print(f"{name}: {wall:.1f} s wall, {peak} MB peak; {'kept' if r['kept'] else 'not kept: ' + r['reason']} ({r['plan']})")
print(f"  machining time {t['before']:.3f} -> {t['after']:.3f} s ({100 * (t['after'] / t['before'] - 1):+.2f} %)")
b, a = r["whole_program"]["before"], r["whole_program"]["after"]
for key in ("speed_fluctuation_mm_min", "speed_inconsistency_p99_mm_min", "speed_inconsistency_mean_mm_min",
            "jerk_p99_mm_s3", "predicted_deviation_p99_um"):
    if b[key] is None or a[key] is None:
        continue
    change = 100 * (a[key] / b[key] - 1) if b[key] else 0.0
    print(f"  {key}: {b[key]:.3f} -> {a[key]:.3f} ({change:+.2f} %)")
print(f"  largest distance between the paths: {r['max_path_distance_mm']:.4f} mm")
PY
  if [ "$name" = cameo.nc ] && awk -v w="$wall" 'BEGIN {exit !(w > 120)}'; then
    echo "optimize_realdata: cameo.nc took ${wall} s, over its 120 s bound" >&2
    status=1
  fi
done
exit $status
