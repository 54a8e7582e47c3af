#!/usr/bin/env bash
# Every example scene (scenes/*.toml) on every sensor through `rangesim simulate`, a few frames each
# (--kernel-only): one line per combination with the exit code, the scene notes, the points and the
# rms range error. Usage: scripts/scene_matrix.sh [path/to/rangesim] [output folder]
set -u
bin=${1:-build/app/rangesim}
out=${2:-$(mktemp -d)}
here=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$out"
export SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1
frames() {
  case $1 in
    ls-conventional) echo "--frames 40" ;;  # 40 of the 375 beam positions of a range map
    ls-demodulation) echo "--frames 40" ;;
    tof-lockin) echo "--frames 2" ;;
    *) echo "--frames 1" ;;
  esac
}
printf '%-28s %-16s %4s %6s %12s %14s %8s\n' scene sensor exit notes valid/points rms_error_mm wall_s
for scene in "$here"/scenes/*.toml; do
  name=$(basename "$scene" .toml)
  for sensor in ls-conventional ls-demodulation tof-lockin tof-spad; do
    start=$(date +%s.%N)
    json=$("$bin" simulate "$sensor" --scene "$scene" $(frames "$sensor") --kernel-only --json --no-plots \
      --out "$out/$name-$sensor" 2>"$out/$name-$sensor.err")
    code=$?
    wall=$(echo "$(date +%s.%N) - $start" | bc)
    notes=$(grep -c "note:" "$out/$name-$sensor.err")
    if [ $code -eq 0 ]; then
      read -r det pts rms < <(echo "$json" | /usr/bin/python3 -c '
import json, sys
j = json.load(sys.stdin)
det = j.get("points_detected", j.get("pixels_detected", j.get("pixel_values_detected", "?")))
pts = j.get("points_visible", j.get("points", j.get("pixel_values", "?")))
rms = j.get("range_error_rms_m")
print(det, pts, "nan" if rms is None else "%.3f" % (rms * 1e3))')
    else
      det="-"; pts="-"; rms="$(head -c 120 "$out/$name-$sensor.err")"
    fi
    printf '%-28s %-16s %4s %6s %12s %14s %8.2f\n' "$name" "$sensor" "$code" "$notes" "$det/$pts" "$rms" "$wall"
  done
done
