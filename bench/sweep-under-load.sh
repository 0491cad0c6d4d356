#!/usr/bin/env bash
# Whether a sweep's timings hold on a loaded machine: the same sweep RUNS times (3) while a CPU
# hog keeps one core busy. Prints each row's median GPU time in every run, how far the runs'
# medians of a row lie apart (slowest / fastest), and whether the runs agree on the Pareto
# front: by the medians, and on the rows each run marks certain (docs/accuracy.md, "Timings
# under load").
#   bench/sweep-under-load.sh [RUNS (3)] [SWEEP.json (bench/sweeps/under-load.json)] [LPV_BENCH]
# The hog is bounded (it ends with this script, and after an hour at most).
set -u
runs="${1:-3}"
root="$(cd "$(dirname "$0")/.." && pwd)"
request="$(realpath "${2:-$root/bench/sweeps/under-load.json}")"
bin="$(realpath "${3:-$root/build/lpv-bench}")"
[ -x "$bin" ] || { echo "sweep-under-load: no lpv-bench at $bin (build first)" >&2; exit 2; }
work=$(mktemp -d)
hog=""
trap '[ -n "$hog" ] && kill "$hog" 2>/dev/null; rm -rf "$work"' EXIT

timeout 3600 sh -c 'while :; do :; done' &
hog=$!
for i in $(seq 1 "$runs"); do
  "$bin" sweep "$request" -q -o "$work/$i" || exit 1
done

# One line per row and run from the CSVs (columns by name): the settings, median, range,
# and the front marks.
for i in $(seq 1 "$runs"); do
  tr -d '\r' <"$work/$i/sweep.csv" | awk -F, -v run="$i" '
    NR == 1 { for (c = 1; c <= NF; ++c) col[$c] = c; next }
    { key = ($col["lpv"] == "true" ? "lpv " $col["grid_x"] "^3 x " $col["iterations"] : "LPV off")
      print NR - 1, run, key, $col["gpu_ms"], $col["gpu_ms_min"], $col["gpu_ms_max"], $col["pareto"], $col["pareto_uncertain"] }'
done >"$work/rows"

awk -v runs="$runs" '
  { row = $1; name[row] = ($3 == "LPV" ? "LPV off" : $3 " " $4 " x " $6); n = NF
    median[row, $2] = $(n - 4); front[row, $2] = $(n - 1); unsure[row, $2] = $n
    if (row > rows) rows = row }
  END {
    printf "%-18s", "row"; for (r = 1; r <= runs; ++r) printf "  run %d (ms, front)  ", r; print "  slowest/fastest"
    worst = 1; same = 1; contradictions = 0
    for (row = 1; row <= rows; ++row) {
      printf "%-18s", name[row]; lo = hi = median[row, 1]
      for (r = 1; r <= runs; ++r) {
        mark = (front[row, r] == "true" ? "on" : "off") (unsure[row, r] == "true" ? "?" : "")
        printf "  %8.2f %-10s", median[row, r], mark
        if (median[row, r] < lo) lo = median[row, r]; if (median[row, r] > hi) hi = median[row, r]
        if (front[row, r] != front[row, 1]) same = 0
        for (q = 1; q < r; ++q)
          if (unsure[row, r] == "false" && unsure[row, q] == "false" && front[row, r] != front[row, q]) ++contradictions
      }
      printf "  %.3f\n", hi / lo; if (hi / lo > worst) worst = hi / lo
    }
    # The same with each run divided by its rows geometric mean: a machine slower for a whole
    # run moves every row alike, and leaves the front alone.
    for (r = 1; r <= runs; ++r) { g[r] = 0; for (row = 1; row <= rows; ++row) g[r] += log(median[row, r]); g[r] = exp(g[r] / rows) }
    relative = 1
    for (row = 1; row <= rows; ++row) {
      lo = hi = median[row, 1] / g[1]
      for (r = 2; r <= runs; ++r) { v = median[row, r] / g[r]; if (v < lo) lo = v; if (v > hi) hi = v }
      if (hi / lo > relative) relative = hi / lo
    }
    printf "\nfronts by the medians: %s; certain marks contradicting each other: %d\n", same ? "identical in every run" : "differ", contradictions
    printf "row medians within %.1f%% of each other across runs; %.1f%% relative to each run'"'"'s geometric mean\n",
      100 * (worst - 1), 100 * (relative - 1) }' "$work/rows"
