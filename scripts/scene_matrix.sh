#!/usr/bin/env bash
# Every example scene (scenes/*.toml) on every registered sensor through `rangesim simulate`
# (--kernel-only): one line per combination with the exit code, the scene notes, the points with a
# valid range, the valid and false-valid fractions and the rms range error. Each sensor runs one
# range map's frames, at most 40 (a light-section map of 375 beam positions is cut to 40).
# Usage: scripts/scene_matrix.sh [path/to/rangesim] [output folder]
set -u
bin=${1:-build/app/rangesim}
out=${2:-$(mktemp -d)}
here=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$out"
export SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1
sensors=$("$bin" list --json | /usr/bin/python3 -c 'import json, sys; print(" ".join(s["id"] for s in json.load(sys.stdin)))')
frames() {  # one range map, at most 40 frames
  "$bin" frame-rate "$1" --json | /usr/bin/python3 -c 'import json, sys; print(min(40, json.load(sys.stdin)["frames_per_range_map"]))'
}
printf '%-28s %-16s %4s %6s %14s %7s %7s %12s %8s\n' scene sensor exit notes valid/points valid false_v rms_mm wall_s
for scene in "$here"/scenes/*.toml; do
  name=$(basename "$scene" .toml)
  for sensor in $sensors; do
    start=$(date +%s.%N)
    json=$("$bin" simulate "$sensor" --scene "$scene" --frames "$(frames "$sensor")" --kernel-only --json --no-plots \
      --force --out "$out/$name-$sensor" 2>"$out/$name-$sensor.err")
    code=$?
    wall=$(echo "$(date +%s.%N) - $start" | bc)
    notes=$(grep -c "note:" "$out/$name-$sensor.err")
    if [ $code -eq 0 ]; then
      read -r counts valid fv rms < <(echo "$json" | /usr/bin/python3 -c '
import json, sys
j = json.load(sys.stdin)
v = j.get("validity", {})
f = lambda x: "-" if x is None else "%.3f" % x
rms = j.get("range_error_rms_m")
print("%s/%s" % (v.get("valid", "?"), v.get("pixels", "?")), f(j.get("valid_fraction")),
      f(j.get("false_valid_fraction")), "nan" if rms is None else "%.3f" % (rms * 1e3))')
    else
      counts="-"; valid="-"; fv="-"; rms="$(head -c 120 "$out/$name-$sensor.err")"
    fi
    printf '%-28s %-16s %4s %6s %14s %7s %7s %12s %8.2f\n' "$name" "$sensor" "$code" "$notes" "$counts" "$valid" "$fv" "$rms" "$wall"
  done
done
