#!/usr/bin/env bash
# Where the GI wins over brute force (docs/accuracy.md): every built-in scene swept at SIZE²
# (128) with the default gather at grids 8³, 16³ and 24³, LPV off and the path tracer at 1, 4,
# 16, 64 and 256 samples per pixel, against a 4096-sample reference over interior pixels. For
# each scene, fits log RMSE against log ms through the path-traced rows (Monte Carlo: a
# slope near -1/2) and prints the time the path tracer needs to reach the 16³ gather's RMSE,
# and the path tracer's FLIP at the gather's time, as the Markdown table the doc shows.
#   bench/gi-vs-path-tracing.sh [SIZE (128)] [LPV_BENCH (build/lpv-bench)]
set -euo pipefail
size="${1:-128}"
root="$(cd "$(dirname "$0")/.." && pwd)"
bin="$(realpath "${2:-$root/build/lpv-bench}")"
[ -x "$bin" ] || { echo "gi-vs-path-tracing: no lpv-bench at $bin (build first)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
scenes="cornell-box cornell-box-point sun-courtyard corridor thin-wall-room open-court gallery-court lone-plane sunlit-hall thin-wall-hut"

echo "| scene | LPV off RMSE | gather 16³: RMSE, ms | path tracing to that RMSE: samples, ms (fit) | GI faster by | gather FLIP | path-traced FLIP at the gather's ms |"
echo "|---|---|---|---|---|---|---|"
for scene in $scenes; do
  cat >"$work/$scene.json" <<JSON
{"base": {"scene": "$scene", "output": {"width": $size, "height": $size}}, "parameters": {"grid": [8, 16, 24]},
 "path_traced": {"samples": [1, 4, 16, 64, 256]}, "reference": {"samples": 4096}, "mask": "interior"}
JSON
  "$bin" sweep "$work/$scene.json" -q -o "$work/$scene" >/dev/null
  # Columns by name; every one used lies before "device", the only field that holds commas.
  awk -F, -v scene="$scene" '
    NR == 1 { for (c = 1; c <= NF; ++c) col[$c] = c; next }
    { samples = $col["path_traced_samples"]; ms = $col["gpu_ms"]; rmse = $col["final_rmse"]; flip = $col["final_flip"] }
    samples == 0 && $col["lpv"] == "false" { off = rmse }
    samples == 0 && $col["lpv"] == "true" && $col["grid_x"] == 16 { g_rmse = rmse; g_ms = ms; g_flip = flip }
    samples > 0 {
      n++; first_ms = (n == 1 ? ms : first_ms); first_rmse = (n == 1 ? rmse : first_rmse)
      if (rmse > 0) { m++; x[m] = log(ms); y[m] = log(rmse); s[m] = log(samples); f[m] = log(flip) }
    }
    function fit(xs, ys, k,   i, mx, my, sxy, sxx) {  # least squares: sets slope and offset
      mx = my = sxy = sxx = 0
      for (i = 1; i <= k; ++i) { mx += xs[i] / k; my += ys[i] / k }
      for (i = 1; i <= k; ++i) { sxy += (xs[i] - mx) * (ys[i] - my); sxx += (xs[i] - mx) ^ 2 }
      slope = sxy / sxx; offset = my - slope * mx
    }
    END {
      if (m < 2) { printf "| %s | %.2g | %.2g, %.0f | exact at 1 sample (%.0f ms): no indirect light | LPV off wins | %.3f | 0 |\n", scene, off, g_rmse, g_ms, first_ms, g_flip; exit }
      fit(s, y, m); spp = exp((log(g_rmse) - offset) / slope)
      fit(x, y, m); pt_ms = exp((log(g_rmse) - offset) / slope)
      fit(x, f, m); pt_flip = exp(offset + slope * log(g_ms))
      if (spp < 1) printf "| %s | %.4f | %.4f, %.0f | 1 sample (%.0f ms) is already better: %.4f | GI loses: %.1f× slower and less accurate | %.3f | %.3f |\n", scene, off, g_rmse, g_ms, first_ms, first_rmse, g_ms / first_ms, g_flip, pt_flip
      else printf "| %s | %.4f | %.4f, %.0f | %.0f, %.0f | %.1f× | %.3f | %.3f |\n", scene, off, g_rmse, g_ms, spp, pt_ms, pt_ms / g_ms, g_flip, pt_flip
    }' "$work/$scene/sweep.csv"
done
