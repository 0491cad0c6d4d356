#!/usr/bin/env bash
# How often lpv-bench ab's verdicts are wrong on a loaded machine: RUNS A/A runs (one build on
# both sides: every REGRESSION is a false alarm) and RUNS A/B runs (B made 1.3x slower with
# --test-slowdown: every run that is not a REGRESSION missed it), all while a CPU hog keeps
# one core busy. Prints each run's one-line verdict and the counts (docs/perf-regression.md,
# "How often the verdicts are wrong").
#   bench/verdict-rates.sh [RUNS (20)] [SUITE (verdicts)] [LPV_BENCH (build/lpv-bench)]
# LPV_VERDICT_RATES_OUT=DIR keeps every run's ab.json there (aa-1/, ab-1/, ...), to see what a
# wrong verdict was made of. The hog is bounded (it ends with this script, and after an hour
# at most).
set -u
runs="${1:-20}"
suite="${2:-verdicts}"
root="$(cd "$(dirname "$0")/.." && pwd)"
bin="$(realpath "${3:-$root/build/lpv-bench}")"
[ -x "$bin" ] || { echo "verdict-rates: no lpv-bench at $bin (build first)" >&2; exit 2; }
work=$(mktemp -d)
hog=""
trap '[ -n "$hog" ] && kill "$hog" 2>/dev/null; rm -rf "$work"' EXIT

# B: the same build, every frame 1.3x as long (busy CPU), as a wrapper ab can start.
slow="$work/slow-lpv-bench"
printf '#!/bin/sh\nexec "%s" "$@" --test-slowdown 1.3\n' "$bin" >"$slow"
chmod +x "$slow"

timeout 3600 sh -c 'while :; do :; done' &
hog=$!

declare -A count
tally() {  # KIND STATUS
  local outcome
  case "$2" in 0) outcome="no regression" ;; 1) outcome="REGRESSION" ;; 4) outcome="inconclusive" ;; *) outcome="error $2" ;; esac
  count["$1: $outcome"]=$(( ${count["$1: $outcome"]:-0} + 1 ))
}
for kind in A/A A/B; do
  b="$bin"; [ "$kind" = A/B ] && b="$slow"
  for i in $(seq 1 "$runs"); do
    out="$work/run"
    [ -n "${LPV_VERDICT_RATES_OUT:-}" ] && out="$LPV_VERDICT_RATES_OUT/$(echo "$kind" | tr -d / | tr AB ab)-$i"
    "$bin" ab --a "$bin" --b "$b" "$suite" -q --no-server -o "$out" >"$work/line" 2>"$work/err"
    status=$?
    printf '%s %2d: %s\n' "$kind" "$i" "$(head -c 300 "$work/line" | tr '\n' ' ')"
    case "$status" in 0 | 1 | 4) ;; *) cat "$work/err" >&2 ;; esac
    tally "$kind" "$status"
  done
done
echo
for key in "${!count[@]}"; do echo "$key: ${count[$key]} of $runs"; done | sort
