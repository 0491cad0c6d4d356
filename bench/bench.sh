#!/usr/bin/env bash
# Prints the numbers the foundation is measured by, on the default device (lavapipe):
#  - per-pass device ms and wall ms per frame for cornell-box at 512x512 with direct light
#    only (median of 20 frames; bench/bench-lpv.sh measures the LPV),
#  - PNG encoding of that frame,
#  - cold start of lpv-render (process start to PNG on disk, default request: LPV on) with
#    empty shader caches,
#    and warm start with Mesa's shader cache and the pipeline cache filled,
# each start time the median of 7 runs. Builds first if needed.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
[ -x "$root/build/lpv-render" ] || "$root/scripts/build.sh"
bin="$root/build/lpv-render"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
runs=7

median() { sort -n | awk '{v[NR]=$1} END {print (NR % 2) ? v[(NR+1)/2] : (v[NR/2] + v[NR/2+1]) / 2}'; }
ms_now() { date +%s%N | awk '{printf "%.3f", $1 / 1e6}'; }
time_run() {  # prints the wall ms of one lpv-render run; env assignments first
  local start end
  start=$(ms_now)
  env "$@" "$bin" -q -o frame.png
  end=$(ms_now)
  awk -v a="$start" -v b="$end" 'BEGIN {printf "%.1f\n", b - a}'
}

echo "== cornell-box 512x512, direct light only (lpv off), median of 20 frames"
echo '{"scene": "cornell-box", "output": {"width": 512, "height": 512}, "lpv": {"enabled": false}, "repeat": 20}' >frame.json
"$bin" frame.json -o frame.png --stats stats.json 2>&1 | sed 's/^/  /'

echo "== start to PNG on disk (median of $runs runs)"
cold=$(for i in $(seq $runs); do
  d=$(mktemp -d -p "$work"); time_run MESA_SHADER_CACHE_DIR="$d" LPV_PIPELINE_CACHE="$d/pipeline.bin"
done | median)
mkdir -p warm
time_run MESA_SHADER_CACHE_DIR="$work/warm" LPV_PIPELINE_CACHE="$work/warm/pipeline.bin" >/dev/null
warm=$(for i in $(seq $runs); do
  time_run MESA_SHADER_CACHE_DIR="$work/warm" LPV_PIPELINE_CACHE="$work/warm/pipeline.bin"
done | median)
echo "  cold (empty caches): ${cold} ms"
echo "  warm (caches filled): ${warm} ms"
