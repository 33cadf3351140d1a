#!/usr/bin/env bash
# Whole-process timing of headless quality maps: a 1,000,000+-sample and a 10,000,000+-sample
# dump (from ../shared/realdata/cameo.nc, a relief raster), rendered to 1600x1000 PNGs.
# Prints wall time and peak memory of each `isurface-cli render` run.
# Usage: bench/render_bench.sh [BUILD_DIR]   (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
cli="$build/bin/isurface-cli"
work=$(mktemp -d /tmp/isurface-render-bench.XXXXXX)
trap 'rm -rf "$work"' EXIT
cameo=../shared/realdata/cameo.nc
[ -f "$cameo" ] || { echo "render_bench: $cameo is missing" >&2; exit 1; }

# At least 1,000,000 samples (1.7 M): the first passes of the program, ended properly.
head -n 1500 "$cameo" > "$work/cameo-1m.nc"
printf 'G0 Z10\nM30\n' >> "$work/cameo-1m.nc"
"$cli" simulate "$work/cameo-1m.nc" -o "$work/cameo-1m.biip" | tail -1
"$cli" simulate "$cameo" -o "$work/cameo-full.biip" | tail -1

for name in cameo-1m cameo-full; do
  program="$work/$name.nc"
  [ "$name" = cameo-full ] && program="$cameo"
  /usr/bin/time -f "$name: %e s wall, %M KB peak" \
    "$cli" render "$program" "$work/$name.biip" --color speed --view iso --size 1600x1000 -o "$work/$name.png"
done
