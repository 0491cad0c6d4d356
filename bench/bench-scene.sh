#!/usr/bin/env bash
# Prints what a glTF scene costs through lpv-server (issue 5's numbers), on the default
# device: upload (parse, validate, store, and the warm-up that makes the scene resident),
# first render, warm render time (median of 5), and the memory the cached scene holds.
#   bench/bench-scene.sh [FILE.glb] [SIZE]
# Default: 2CylinderEngine.glb from assimp-testmodels, 512x512. Needs only curl. Builds first
# if needed.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
[ -x "$root/build/lpv-server" ] || "$root/scripts/build.sh"
file="${1:-/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb}"
size="${2:-512}"
work=$(mktemp -d)

. "$root/bench/local_server.sh"
start_local_server "$root/build/lpv-server"
base="http://127.0.0.1:$port"
ms() { awk '{printf "%.1f ms", $1 * 1000}'; }
cache_bytes() { curl -s "$base/metrics" | awk '/^lpv_scene_cache_bytes/ {print $2}'; }

echo "== $(basename "$file"), ${size}x${size}, LPV on (the default request)"
before=$(cache_bytes)  # before the upload: it makes the scene resident (Renderer::prepare)
upload=$(curl -s -o "$work/scene.json" -w '%{time_total}' -H 'Content-Type: application/octet-stream' \
  --data-binary @"$file" "$base/v1/scenes")
id=$(sed -n 's/.*"id":"\([0-9a-f]*\)".*/\1/p' "$work/scene.json")
[ -n "$id" ] || { echo "upload refused: $(cat "$work/scene.json")"; exit 1; }
echo "upload (parse, validate, store, warm up): $(echo "$upload" | ms)"
body="{\"scene\": \"$id\", \"output\": {\"width\": $size, \"height\": $size}}"
render() { curl -s -f -o /dev/null -w '%{time_total}\n' -H 'Content-Type: application/json' -d "$body" "$base/v1/render"; }
echo "first render (the scene resident since the upload; PNG): $(render | ms)"
echo "cached scene: $(( ($(cache_bytes) - before) / 1024 )) KiB (host and device copies)"
for _ in 1 2 3 4 5; do render; done | sort -n | sed -n 3p | { read -r t; echo "warm render, median of 5: $(echo "$t" | ms)"; }
