#!/usr/bin/env bash
# Records the reference programs on LinuxCNC 2.9's real trajectory planner and keeps them as
# test data (tests/data/linuxcnc-2.9/): each program, and its recording in halsampler's format
# (one row per 1 ms servo cycle: index, x, y, z, program line, current and requested velocity,
# running) without the idle rows before the first motion and after the last, compressed.
#
#   bash tools/linuxcnc-reference/record.sh [NAME...]     as root, on a machine with LinuxCNC
#
# Needs LinuxCNC 2.9 (apt-get install --no-install-recommends linuxcnc-uspace), a user `lcnc`
# (useradd -m lcnc) and the peer's headless configuration, ../shared/tools/linuxcnc-sim beside
# the clone or named by LINUXCNC_SIM. It runs in real time: all programs take about 15 minutes.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
sim=${LINUXCNC_SIM:-$root/../shared/tools/linuxcnc-sim}
data=$root/tests/data/linuxcnc-2.9
[ -x "$sim/run.sh" ] || { echo "record.sh: no $sim/run.sh (set LINUXCNC_SIM)" >&2; exit 2; }
command -v linuxcnc >/dev/null || { echo "record.sh: LinuxCNC is not installed" >&2; exit 2; }
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
python3 "$here/make_programs.py" "$scratch/programs" >/dev/null
mkdir -p "$data"
cp "$scratch/programs/manifest.json" "$data/manifest.json"
names=("$@")
if [ ${#names[@]} -eq 0 ]; then
  for program in "$scratch"/programs/*.ngc; do names+=("$(basename "$program" .ngc)"); done
fi
for name in "${names[@]}"; do
  program=$scratch/programs/$name.ngc
  [ -f "$program" ] || { echo "record.sh: no program $name" >&2; exit 2; }
  echo "recording $name ($(wc -l <"$program") lines)"
  bash "$sim/run.sh" "$program" "$scratch/$name.txt" >/dev/null
  # Rows from the last cycle before the first motion to the last cycle with motion.
  awk '{ n++; row[n] = $0; x[n] = $2; y[n] = $3; z[n] = $4 }
       END {
         for (i = 2; i <= n; i++) if (x[i] != x[i-1] || y[i] != y[i-1] || z[i] != z[i-1]) { if (!f) f = i; l = i }
         for (i = f - 1; i <= l; i++) print row[i]
       }' "$scratch/$name.txt" | gzip -9n >"$data/$name.halsampler.txt.gz.part"
  mv "$data/$name.halsampler.txt.gz.part" "$data/$name.halsampler.txt.gz"
  cp "$program" "$data/$name.ngc"
done
