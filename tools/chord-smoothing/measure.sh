#!/bin/bash
# The generic control's chord smoothing on the default machine, against the same machine whose
# control has no compressor: motion time and the share of moving samples at the feed, for each
# program given. Writes its dumps to a scratch folder.
# usage: tools/chord-smoothing/measure.sh PROGRAM...
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
cli=${ISURFACE_CLI:-$root/build/bin/isurface-cli}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
for program in "$@"; do
  name=$(basename "$program")
  "$cli" simulate "$program" -o "$scratch/smoothed.biip" >/dev/null
  "$cli" simulate "$program" -o "$scratch/braking.biip" \
    --machine "$root/resources/machines/without-chord-smoothing.json" >/dev/null
  smoothed=$(python3 "$here/feed_share.py" "$scratch/smoothed.biip" | cut -f2,3)
  braking=$(python3 "$here/feed_share.py" "$scratch/braking.biip" | cut -f2,3)
  printf '%s\twithout a compressor: %s\twith: %s\n' "$name" "$braking" "$smoothed"
done
