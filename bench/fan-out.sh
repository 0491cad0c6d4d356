#!/usr/bin/env bash
# Fan-out over replicas (docs/perf-regression.md, "Fan-out over replicas"): a suite, or a sweep,
# through REPLICAS lpv-server processes on one data dir behind HAProxy (docker/haproxy.cfg),
# once with --jobs 1 and once with --jobs REPLICAS. Prints both runs' wall time, the speed-up,
# and whether the two results agree (they must): a suite's cases and images, a sweep's rows
# with their settings and errors.
#   bench/fan-out.sh [REPLICAS (2)] [run SUITE | sweep REQUEST.json (run default)] [BUILD (build)]
# Everything it starts listens on loopback and ends with it.
set -euo pipefail
replicas="${1:-2}"
command="${2:-run}"
input="${3:-default}"
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$(realpath "${4:-$root/build}")"
case "$command" in
  run) ;;
  sweep) input="$(realpath "$input")" ;;
  *) echo "fan-out: the second argument is run or sweep, got '$command'" >&2; exit 2 ;;
esac
haproxy="$(command -v haproxy || echo /usr/sbin/haproxy)"
for program in "$build/lpv-server" "$build/lpv-bench" "$haproxy"; do
  [ -x "$program" ] || { echo "fan-out: $program missing (build first; scripts/install-deps.sh installs haproxy)" >&2; exit 2; }
done
work=$(mktemp -d)
pids=()
trap 'for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done; wait 2>/dev/null; rm -rf "$work"' EXIT

# The replicas, each on a free port it prints as its first line.
{ echo "frontend lpv"; echo "  bind 127.0.0.1:\${LB_PORT}"; echo "  default_backend replicas"; echo "backend replicas"; } >"$work/replicas.cfg"
for i in $(seq 1 "$replicas"); do
  : >"$work/server$i.log"  # before the server starts: the wait below reads it at once
  "$build/lpv-server" --port 0 --data-dir "$work/data" >"$work/server$i.log" 2>&1 &
  pids+=($!)
  for _ in $(seq 1 600); do grep -q 'listening on' "$work/server$i.log" && break; sleep 0.1; done
  port=$(sed -n 's/.*listening on http:\/\/127.0.0.1:\([0-9]*\).*/\1/p' "$work/server$i.log" | head -1)
  [ -n "$port" ] || { cat "$work/server$i.log" >&2; exit 1; }
  echo "  server r$i 127.0.0.1:$port" >>"$work/replicas.cfg"
done

# HAProxy on a port picked at random, again on another if it is taken.
for _ in 1 2 3 4 5; do
  export LB_PORT=$((20000 + RANDOM % 20000))
  "$haproxy" -db -f "$root/docker/haproxy.cfg" -f "$work/replicas.cfg" >"$work/haproxy.log" 2>&1 &
  pids+=($!)
  for _ in $(seq 1 100); do curl -fs "http://127.0.0.1:$LB_PORT/readyz" >/dev/null && break 2; sleep 0.1; done
done
curl -fs "http://127.0.0.1:$LB_PORT/readyz" >/dev/null || { cat "$work/haproxy.log" >&2; exit 1; }

run() {  # JOBS: the results in $work/jobs-JOBS(.json or /); prints the wall seconds
  local start end
  start=$(date +%s.%N)
  if [ "$command" = run ]; then
    "$build/lpv-bench" run "$input" --url "http://127.0.0.1:$LB_PORT" --jobs "$1" -q -o "$work/jobs-$1.json" --label "jobs $1"
  else
    "$build/lpv-bench" sweep "$input" --url "http://127.0.0.1:$LB_PORT" --jobs "$1" -q -o "$work/jobs-$1" >/dev/null
  fi
  end=$(date +%s.%N)
  echo "$start $end" | awk '{ printf "%.1f", $2 - $1 }'
}
# What must not depend on the jobs: a suite's images, a sweep's rows but their times.
outcome() {
  if [ "$command" = run ]; then
    grep -o '"sha256": *"[0-9a-f]*"' "$work/jobs-$1.json"
  else
    awk -F, 'NR == 1 { for (c = 1; c <= NF; ++c) keep[c] = $c !~ /gpu_ms|wall_ms|frames|pareto/ }
             { line = ""; for (c = 1; c <= NF; ++c) if (keep[c]) line = line $c ","; print line }' "$work/jobs-$1/sweep.csv"
  fi
}

serial=$(run 1)
fanned=$(run "$replicas")
echo "$command $(basename "$input") through $replicas replicas behind HAProxy, $(nproc) cores:"
echo "  --jobs 1: ${serial} s"
echo "  --jobs $replicas: ${fanned} s"
echo "$serial $fanned" | awk '{ printf "  speed-up: %.2f\n", $1 / $2 }'
if [ -n "$(outcome 1)" ] && [ "$(outcome 1)" = "$(outcome "$replicas")" ]; then
  echo "  the same results in both runs (times aside)"
else
  echo "fan-out: the two runs' results differ" >&2
  exit 1
fi
