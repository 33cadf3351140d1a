#!/usr/bin/env bash
# `isurface-cli canon FILE -o OUT` against LinuxCNC's `rs274 -g FILE OUT` on a 1,000,000-line
# raster of plain `G1 X.. Y.. Z..` moves (30 MB), both as whole processes writing their moves to
# a file, alternated in the same run so that both see the same machine load. Prints each run's
# wall time, the medians and their ratio (target: canon at least 30 times faster).
# Without rs274 (LinuxCNC's `linuxcnc-uspace` package) it times canon alone and says so.
# Usage: bench/canon_vs_rs274.sh [BUILD_DIR [RUNS]]   (default: build, 5)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
runs=${2:-5}
cli="$build/bin/isurface-cli"
[ -x "$cli" ] || { echo "canon_vs_rs274: $cli is missing (build first)" >&2; exit 1; }
rs274=$(command -v rs274 || true)
[ -n "$rs274" ] || echo "canon_vs_rs274: rs274 is not installed: timing canon alone"
work=$(mktemp -d /tmp/isurface-canon-rs274.XXXXXX)
trap 'rm -rf "$work"' EXIT

# A zig-zag over 5,000 rows of 200 points, 0.5 mm apart, Z from a fixed pseudo-random sequence
# (so that the numbers do not repeat), 4 decimals as CAM programs write them.
awk 'BEGIN {
  print "G21 G90 G17"; print "G0 X0 Y0 Z5"; print "G1 Z0 F1200"
  seed = 12345
  for (row = 0; row < 5000; ++row)
    for (k = 0; k < 200; ++k) {
      i = row % 2 ? 199 - k : k
      seed = (seed * 1103515245 + 12345) % 2147483648
      printf "G1 X%.4f Y%.4f Z%.4f\n", i * 0.5, row * 0.2, seed / 2147483648 * 0.3
    }
  print "M2"
}' > "$work/raster.nc"
printf 'input: %d lines, %d bytes\n' "$(wc -l < "$work/raster.nc")" "$(stat -c %s "$work/raster.nc")"

# elapsed COMMAND...: the command's wall time in seconds (stdin from /dev/null, output discarded).
elapsed() {
  local start=$EPOCHREALTIME
  "$@" < /dev/null > /dev/null 2> "$work/err" || { echo "failed: $*" >&2; cat "$work/err" >&2; exit 1; }
  local stop=$EPOCHREALTIME
  awk -v a="$start" -v b="$stop" 'BEGIN { printf "%.4f\n", b - a }'
}
median() { sort -g | awk '{ v[NR] = $1 } END { print NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

"$cli" canon "$work/raster.nc" -o "$work/warm.canon" > /dev/null  # the file in the page cache
: > "$work/ours.txt"
: > "$work/rs274.txt"
for ((i = 1; i <= runs; ++i)); do
  ours=$(elapsed "$cli" canon "$work/raster.nc" -o "$work/ours.canon")
  echo "$ours" >> "$work/ours.txt"
  line="run $i: canon ${ours} s"
  if [ -n "$rs274" ]; then
    theirs=$(elapsed "$rs274" -g "$work/raster.nc" "$work/rs274.canon")
    echo "$theirs" >> "$work/rs274.txt"
    line+=", rs274 ${theirs} s"
  fi
  echo "$line"
done
ours=$(median < "$work/ours.txt")
printf 'median: canon %.4f s (%d output lines)\n' "$ours" "$(wc -l < "$work/ours.canon")"
if [ -n "$rs274" ]; then
  theirs=$(median < "$work/rs274.txt")
  awk -v a="$ours" -v b="$theirs" \
    'BEGIN { printf "median: rs274 %.4f s; canon is %.1f times faster (target 30)\n", b, b / a }'
fi
