#!/usr/bin/env bash
# Prints the numbers the LPV is measured by, on the default device (lavapipe): per-pass
# device ms of cornell-box at 512x512 (median of 10 frames) for grids of 16^3, 32^3 and 64^3
# cells and 4, 8 and 16 iterations (one cascade, RSM 256^2, occlusion on, plan exact), and propagation
# throughput in cell-iterations per second. Builds first if needed.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
[ -x "$root/build/lpv-render" ] || "$root/scripts/build.sh"
bin="$root/build/lpv-render"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

printf '%-6s %-5s %s\n' grid iters "per-pass device ms (median of 10 frames) | propagation throughput"
for grid in 16 32 64; do
  for iterations in 4 8 16; do
    # Plan "exact": at 16^3 the planner would lower the RSM to 128 (docs/planner.md).
    echo "{\"output\": {\"width\": 512, \"height\": 512}, \"repeat\": 10, \"plan\": \"exact\",
           \"lpv\": {\"grid\": $grid, \"iterations\": $iterations}}" >request.json
    out=$("$bin" request.json -o frame.png 2>&1) || {
      echo "bench-lpv.sh: lpv-render failed (grid $grid, $iterations iterations):" >&2
      echo "$out" >&2
      exit 1
    }
    # The summary's second line: "gpu T ms (median): shadow a rsm b ... propagate p ...".
    sed -n 2p <<<"$out" | awk -v g="$grid" -v n="$iterations" '{
      for (i = 1; i <= NF; ++i) if ($i == "propagate") p = $(i + 1);
      if (p == "") { print "bench-lpv.sh: no propagate time in: " $0 > "/dev/stderr"; exit 1 }
      sub(/^ +gpu /, "total ");
      rate = (p > 0) ? g * g * g * n / (p / 1000) : 0;
      printf "%-6s %-5s %s | %.1f M cell-iterations/s\n", g "^3", n, $0, rate / 1e6 }'
  done
done
