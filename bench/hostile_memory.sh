#!/usr/bin/env bash
# Programs that cost nothing to write and once cost gigabytes to read: millions of zero-length
# moves, millions of `G4 P0`, and a program read from a pipe. `simulate` and `canon` must stay
# within what isurface-cli takes to start plus 64 MB on each (docs/benchmarks.md, Large inputs). Each run is
# a whole process measured by /usr/bin/time (Debian package `time`): wall time and peak resident
# set size. Exits 1 when a run fails or exceeds its bound.
# Usage: bench/hostile_memory.sh [BUILD_DIR [LINES]]   (default: build, 5000000)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
lines=${2:-5000000}
cli="$build/bin/isurface-cli"
[ -x "$cli" ] || { echo "hostile_memory: $cli is missing (build first)" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "hostile_memory: /usr/bin/time is missing (apt-get install time)" >&2; exit 1; }
work=$(mktemp -d /tmp/isurface-hostile.XXXXXX)
trap 'rm -rf "$work"' EXIT

awk -v n="$lines" 'BEGIN { print "G21 G90 G1 X1 F1000"; for (i = 0; i < n; ++i) print "G1 X1"; print "M2" }' > "$work/zero-length.nc"
awk -v n="$lines" 'BEGIN { print "G21 G90 G1 X1 F1000"; for (i = 0; i < n; ++i) print "G4 P0"; print "M2" }' > "$work/dwell-zero.nc"
awk -v n="$lines" 'BEGIN { print "G21 G90 G1 F1000"; for (i = 0; i < n; ++i) printf "G1 X%.3f Y%.3f\n", (i % 200) * 0.5, int(i / 200) * 0.2; print "M2" }' > "$work/raster.nc"
printf 'G21 G90\nM2\n' > "$work/one-line.nc"

# peak KB and seconds of a command
measure() {
  /usr/bin/time -f '%M %e' -o "$work/time" "$@" > /dev/null 2> "$work/err" || { echo "failed: $*" >&2; cat "$work/err" >&2; exit 1; }
  cat "$work/time"
}
read -r start _ < <(measure "$cli" simulate "$work/one-line.nc" -o /dev/null)
bound=$((start + 64 * 1024))
printf 'start-up: %d KB; bound: %d KB (%d lines each)\n' "$start" "$bound" "$lines"
status=0
check() {  # name command...
  local name=$1; shift
  read -r kb seconds < <(measure "$@")
  local verdict=ok
  [ "$kb" -le "$bound" ] || { verdict=OVER; status=1; }
  printf '%-34s %8d KB %7.2f s  %s\n' "$name" "$kb" "$seconds" "$verdict"
}
check "simulate zero-length moves" "$cli" simulate "$work/zero-length.nc" -o /dev/null
check "simulate G4 P0" "$cli" simulate "$work/dwell-zero.nc" -o /dev/null
check "canon zero-length moves" "$cli" canon "$work/zero-length.nc" -o /dev/null
check "canon G4 P0" "$cli" canon "$work/dwell-zero.nc" -o /dev/null
check "canon raster from a pipe" sh -c "cat '$work/raster.nc' | '$cli' canon /dev/stdin -o /dev/null"
check "simulate raster from a pipe" sh -c "cat '$work/raster.nc' | '$cli' simulate /dev/stdin -o /dev/null"
exit $status
