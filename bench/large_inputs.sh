#!/usr/bin/env bash
# Large inputs within stated memory bounds: a 2 GB G-code file (a long zig-zag raster over a
# wavy surface, 0.5 mm G1 moves) and a 10,000,000-sample Biip dump simulated from its first
# part. Each run is a whole process, timed by /usr/bin/time -v (Debian package `time`): wall
# time and peak resident set size. The bounds are over what isurface-cli itself takes to start
# (its libraries: measured first, on a one-line program):
#   canon    on the 2 GB file (output to /dev/null)                  start + 64 MB, any size
#   simulate on the 2 GB file (all ~900 M samples, a 57 GB dump,
#            streamed to /dev/null: every sample is made and written) start + 64 MB, any length
#   simulate of the first part into a 10 M-sample dump                start + 64 MB
#   info     on the 10 M-sample dump                                  start + 64 MB + 64 B/sample (the mapped file)
#   render   of the 10 M-sample dump, 1600x1000                       200 B/sample (2 GB)
# It exits 1 when a run fails or exceeds its bound. The files are made in WORK_DIR (default: a
# new folder in /tmp; about 2.9 GB free needed) and deleted afterwards.
# Usage: bench/large_inputs.sh [BUILD_DIR [WORK_DIR]]   (default: build, /tmp)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
cli="$build/bin/isurface-cli"
[ -x "$cli" ] || { echo "large_inputs: $cli is missing (build first)" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "large_inputs: /usr/bin/time is missing (apt-get install time)" >&2; exit 1; }
work=$(mktemp -d "${2:-/tmp}/isurface-large.XXXXXX")
trap 'rm -rf "$work"' EXIT

gcode_bytes=$((2 * 1024 * 1024 * 1024))
biip_samples=10000000

# One tile: a zig-zag raster of 100 passes of 400 moves, ending where the next tile starts.
# The 2 GB file repeats it; the dump's program is its first tiles.
python3 - "$work" "$gcode_bytes" <<'EOF'
import math, sys
work, total = sys.argv[1], int(sys.argv[2])
lines = []
for p in range(100):
    y = p * 0.25
    xs = range(401) if p % 2 == 0 else range(400, -1, -1)
    for k, i in enumerate(xs):
        x = i * 0.5
        z = 0.8 * math.sin(x / 9.0) * math.cos(y / 7.0)
        lines.append(f"X{x:.3f} Y{y:.3f} Z{z:.4f}\n" if k else f"G1 X{x:.3f} Y{y:.3f} Z{z:.4f}\n")
lines.append("G0 Z2\nX0 Y0\nG1 Z0.8 F3000\n")
tile = "".join(lines).encode()
head = b"G21 G90 G17 G64 F3000 S12000 M3\nG0 X0 Y0 Z2\nG1 Z0.8\n"
tail = b"G0 Z10\nM5\nM30\n"
with open(f"{work}/raster-2gb.nc", "wb") as f:
    f.write(head)
    written = len(head)
    while written + len(tile) + len(tail) <= total:
        f.write(tile)
        written += len(tile)
    f.write(tail)
with open(f"{work}/raster-prefix.nc", "wb") as f:
    f.write(head + tile * 25 + tail)
EOF

failed=0
# run NAME BOUND_KB COMMAND...: the whole process under /usr/bin/time -v.
run() {
  local name=$1 bound_kb=$2
  shift 2
  if ! /usr/bin/time -v -o "$work/time.txt" "$@" > "$work/out.txt" 2> "$work/err.txt"; then
    echo "$name: FAILED" >&2
    cat "$work/err.txt" >&2
    failed=1
    return
  fi
  local wall peak
  wall=$(sed -n 's/.*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$work/time.txt")
  peak=$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$work/time.txt")
  local verdict=ok
  if [ "$peak" -gt "$bound_kb" ]; then verdict="OVER THE BOUND"; failed=1; fi
  awk -v n="$name" -v w="$wall" -v p="$peak" -v b="$bound_kb" -v v="$verdict" \
    'BEGIN { printf "%-50s %9s wall %8.1f MB peak (bound %7.1f MB)  %s\n", n, w, p / 1024, b / 1024, v }'
}

printf 'G0 X1\n' > "$work/one-line.nc"
run "start: canon, one-line G-code" $((1024 * 1024)) "$cli" canon "$work/one-line.nc" -o /dev/null
start_kb=$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$work/time.txt")
small_kb=$((start_kb + 64 * 1024))

gcode="$work/raster-2gb.nc"
lines=$(wc -l < "$gcode")
printf 'G-code: %s, %d bytes, %d lines\n' "$gcode" "$(stat -c %s "$gcode")" "$lines"
run "canon, 2 GB G-code -> /dev/null" $small_kb "$cli" canon "$gcode" -o /dev/null
run "simulate, 2 GB G-code -> /dev/null" $small_kb "$cli" simulate "$gcode" -o /dev/null --max-hours 1000
tail -1 "$work/out.txt"

run "simulate, first part -> 10 M-sample dump" $small_kb \
  "$cli" simulate "$work/raster-prefix.nc" -o "$work/raster.biip"
tail -1 "$work/out.txt"
samples=$(sed -n 's/.*(\([0-9.]*\) s), \([0-9]*\) samples.*/\2/p' "$work/out.txt")
if [ -z "$samples" ] || [ "$samples" -lt "$biip_samples" ]; then
  echo "the dump has ${samples:-no} samples, fewer than $biip_samples" >&2
  failed=1
  samples=$biip_samples
fi
run "info, $samples-sample dump" $((small_kb + samples * 64 / 1024)) "$cli" info "$work/raster.biip"
run "render, $samples-sample dump, 1600x1000" $((samples * 200 / 1024)) \
  "$cli" render "$work/raster.biip" --color speed --view iso --size 1600x1000 -o "$work/raster.png"
exit $failed
