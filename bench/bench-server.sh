#!/usr/bin/env bash
# Prints the numbers lpv-server is measured by (issue 4), on the default device (lavapipe):
#  - warm POST /v1/render latency, median and p99, PNG included, one client on one
#    keep-alive connection, at 256x256 and 512x512 (cornell-box);
#  - sustained requests/s at 256x256 with 4 concurrent clients;
#  - the first render of a newly uploaded scene against its steady frame (PNG and EXR);
#  - the server's RSS after 10 and after 1000 requests (256x256, 4 clients, direct light
#    unless RSS_LPV=on).
# Each render is measured twice: the default request (LPV on) and with
# "lpv": {"enabled": false} (direct light only), which separates the renderer's cost
# from the service's. Needs only curl. Builds first if needed.
# Environment: LATENCY_REQUESTS (default 50), RPS_REQUESTS per client (25), RSS_REQUESTS (1000),
# RSS_LPV (off), LPV_SERVER_BINARY (build/lpv-server).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
[ -x "$root/build/lpv-server" ] || "$root/scripts/build.sh"
bin="${LPV_SERVER_BINARY:-$root/build/lpv-server}"
latency_requests=${LATENCY_REQUESTS:-50}
rps_requests=${RPS_REQUESTS:-25}
rss_requests=${RSS_REQUESTS:-1000}
rss_lpv=${RSS_LPV:-off}  # "on" takes 1000 LPV renders (minutes on lavapipe)
[ "$rss_requests" -ge 10 ] 2>/dev/null || { echo "RSS_REQUESTS must be a number of at least 10 (the first 10 are the baseline), got '$rss_requests'" >&2; exit 2; }
work=$(mktemp -d)

. "$root/bench/local_server.sh"
start_local_server "$bin" --queue 64
url="http://127.0.0.1:$port/v1/render"

body() {  # body SIZE LPV(on|off)
  local lpv=""
  [ "$2" = off ] && lpv=', "lpv": {"enabled": false}'
  echo "{\"output\": {\"width\": $1, \"height\": $1}$lpv}"
}
# N requests on one connection (curl reuses it); prints each one's total seconds.
client() {  # client N BODY
  local config="$work/curl.$BASHPID"
  printf 'data = "%s"\n' "${2//\"/\\\"}" >"$config"
  for _ in $(seq "$1"); do printf 'url = "%s"\noutput = "/dev/null"\n' "$url" >>"$config"; done
  curl -s -f -H 'Content-Type: application/json' -w '%{time_total}\n' --config "$config"
}
percentiles() {  # seconds in, "median X ms, p99 Y ms" out
  sort -n | awk '{v[NR] = $1 * 1000} END {
    m = (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2
    p = int(0.99 * NR + 0.999); if (p < 1) p = 1
    printf "median %.1f ms, p99 %.1f ms (%d requests)\n", m, v[p], NR}'
}
rss_kib() { awk '/^VmRSS/ {print $2}' "/proc/$server/status"; }
now() { date +%s.%N; }

echo "== warm latency, one client (cornell-box, PNG included)"
for lpv in on off; do
  for size in 256 512; do
    client 3 "$(body "$size" "$lpv")" >/dev/null  # warm: targets of this size, caches
    printf '  %sx%s lpv %-3s  ' "$size" "$size" "$lpv"
    client "$latency_requests" "$(body "$size" "$lpv")" | percentiles
  done
done

echo "== throughput, 4 concurrent clients, 256x256"
for lpv in on off; do
  start=$(now)
  clients=()
  for i in 1 2 3 4; do client "$rps_requests" "$(body 256 "$lpv")" >"$work/rps.$lpv.$i" & clients+=($!); done
  wait "${clients[@]}"  # not a bare wait: the server is a background job too
  end=$(now)
  done_count=$(cat "$work"/rps."$lpv".* | wc -l)
  awk -v n="$done_count" -v a="$start" -v b="$end" -v l="$lpv" \
    'BEGIN {printf "  lpv %-3s  %.1f requests/s (%d requests in %.1f s)\n", l, n / (b - a), n, b - a}'
done

echo "== first render of a new upload against its steady frame (256x256, round trips; docs/server.md)"
# The upload warms the scene up on the worker (Renderer::prepare); its first render should
# cost what the later ones do. Scenes from assimp-testmodels: a textured box, an engine.
for scene in /usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb \
             /usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb; do
  [ -f "$scene" ] || { echo "  $(basename "$scene"): not installed (assimp-testmodels)"; continue; }
  id=$(curl -s -f -H 'Content-Type: model/gltf-binary' --data-binary "@$scene" "http://127.0.0.1:$port/v1/scenes" |
       sed -n 's/.*"id": *"\([0-9a-f]*\)".*/\1/p')
  for format in png exr; do
    request="{\"scene\": \"$id\", \"output\": {\"width\": 256, \"height\": 256, \"format\": \"$format\"}}"
    client 6 "$request" >"$work/first" || true
    first=$(head -1 "$work/first")
    tail -n +2 "$work/first" | sort -n | awk -v name="$(basename "$scene") $format" -v first="$first" \
      '{v[NR] = $1 * 1000} END {m = (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2
        printf "  %-26s first %.1f ms, steady median %.1f ms: %.2fx\n", name, first * 1000, m, first * 1000 / m}'
  done
done

echo "== server RSS, 256x256, 4 clients (lpv $rss_lpv), counted from here"
client 10 "$(body 256 "$rss_lpv")" >/dev/null
rss10=$(rss_kib)
rest=$((rss_requests - 10))
clients=()
for i in 0 1 2 3; do  # the rest split over 4 clients, the first taking the remainder
  count=$((rest / 4 + (i == 0 ? rest % 4 : 0)))
  [ "$count" -gt 0 ] || continue
  client "$count" "$(body 256 "$rss_lpv")" >/dev/null &
  clients+=($!)
done
wait "${clients[@]}"
rss_end=$(rss_kib)
awk -v a="$rss10" -v b="$rss_end" -v n="$rss_requests" \
  'BEGIN {printf "  after 10 requests: %.1f MiB; after %d: %.1f MiB (%+.1f%%)\n", a / 1024, n, b / 1024, (b - a) * 100 / a}'
