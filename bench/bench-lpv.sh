#!/usr/bin/env bash
# Prints the numbers the LPV is measured by, on the default device (lavapipe).
#   bench/bench-lpv.sh [passes]   per-pass device ms of cornell-box at 512x512 (median of 10
#                                   frames) for grids of 16^3, 32^3 and 64^3 cells and 4, 8 and 16
#                                   iterations (one cascade, RSM 256^2, occlusion on, plan exact),
#                                   and propagation throughput in cell-iterations per second.
#   bench/bench-lpv.sh scaling    what one propagation step costs from 4^3 to 64^3 cells (16
#                                   iterations, median of 10 frames): microseconds a step and
#                                   nanoseconds a cell-iteration, with occlusion and without,
#                                   which tell the fixed cost of a step (a dispatch and its
#                                   barrier) from the cost of a cell and show where the grids
#                                   stop fitting the cache; then what memcpy moves on two
#                                   threads, to set the largest grids' traffic against.
# Builds first if needed.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
mode=${1:-passes}
[[ "$mode" == passes || "$mode" == scaling ]] || { echo "usage: bench/bench-lpv.sh [passes|scaling]" >&2; exit 2; }
[ -x "$root/build/lpv-render" ] || "$root/scripts/build.sh"
bin="$root/build/lpv-render"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

# Renders cornell-box with the given output size, grid, iterations and occlusion (default
# true; plan "exact": at 16^3 the planner would lower the RSM to 128, docs/planner.md) and
# prints the summary's second line: "gpu T ms (median): shadow a rsm b ... propagate p ...".
summary_line() {
  local size=$1 grid=$2 iterations=$3 occlusion=${4:-true} out
  echo "{\"output\": {\"width\": $size, \"height\": $size}, \"repeat\": 10, \"plan\": \"exact\",
         \"lpv\": {\"grid\": $grid, \"iterations\": $iterations, \"occlusion\": $occlusion}}" >request.json
  out=$("$bin" request.json -o frame.png 2>&1) || {
    echo "bench-lpv.sh: lpv-render failed (grid $grid, $iterations iterations):" >&2
    echo "$out" >&2
    exit 1
  }
  sed -n 2p <<<"$out"
}

# The propagate time in a summary line, or a failure naming the line.
propagate_ms() {
  awk '{ for (i = 1; i <= NF; ++i) if ($i == "propagate") p = $(i + 1)
         if (p == "") { print "bench-lpv.sh: no propagate time in: " $0 > "/dev/stderr"; exit 1 }
         print p }'
}

if [ "$mode" = scaling ]; then
  # 64x64 output: the forward pass is then a small part of each frame; propagation does not
  # depend on the output size.
  iterations=16
  printf '%-15s %-24s %s\n' "" "occlusion on" "occlusion off"
  printf '%-6s %-8s %-9s %-14s %-9s %s\n' grid cells us/step ns/cell-it us/step ns/cell-it
  for grid in 4 8 16 24 32 40 48 56 64; do
    occluded=$(summary_line 64 "$grid" "$iterations" | propagate_ms)
    open=$(summary_line 64 "$grid" "$iterations" false | propagate_ms)
    awk -v g="$grid" -v n="$iterations" -v p="$occluded" -v q="$open" 'BEGIN {
      cells = g * g * g
      printf "%-6s %-8d %-9.1f %-14.1f %-9.1f %.1f\n", g "^3", cells, p * 1000 / n, p * 1e6 / (cells * n),
             q * 1000 / n, q * 1e6 / (cells * n) }'
  done
  # The memory's bandwidth for the same two threads: 256 MB copied, halves in parallel, best of 5.
  cat >memcpy.cpp <<'CPP'
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <thread>
#include <vector>
int main() {
  const std::size_t n = std::size_t(256) << 20;
  std::vector<char> a(n, 1), b(n, 2);
  double best = 0;
  for (int r = 0; r < 5; ++r) {
    const auto start = std::chrono::steady_clock::now();
    std::thread half([&] { std::memcpy(b.data(), a.data(), n / 2); });
    std::memcpy(b.data() + n / 2, a.data() + n / 2, n / 2);
    half.join();
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    best = std::max(best, 2.0 * n / s / 1e9);
  }
  std::printf("memcpy of 256 MB on 2 threads: %.1f GB/s read and written (best of 5)\n", best);
}
CPP
  c++ -O2 -pthread memcpy.cpp -o memcpy && ./memcpy
  exit 0
fi

printf '%-6s %-5s %s\n' grid iters "per-pass device ms (median of 10 frames) | propagation throughput"
for grid in 16 32 64; do
  for iterations in 4 8 16; do
    line=$(summary_line 512 "$grid" "$iterations")
    p=$(propagate_ms <<<"$line")
    awk -v g="$grid" -v n="$iterations" -v p="$p" -v line="$line" 'BEGIN {
      sub(/^ +gpu /, "total ", line)
      rate = (p > 0) ? g * g * g * n / (p / 1000) : 0
      printf "%-6s %-5s %s | %.1f M cell-iterations/s\n", g "^3", n, line, rate / 1e6 }'
  done
done
