#!/usr/bin/env bash
# Prints what a glTF scene costs through lpv-server (issue 5's numbers), on the default
# device: upload (parse, validate, store), first render (load, upload to the device,
# render), warm render time (median of 5), and the memory the cached scene holds.
#   bench/bench-scene.sh [FILE.glb] [SIZE]
# Default: 2CylinderEngine.glb from assimp-testmodels, 512x512. Needs only curl. Builds first
# if needed.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
[ -x "$root/build/lpv-server" ] || "$root/scripts/build.sh"
file="${1:-/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb}"
size="${2:-512}"
work=$(mktemp -d)

"$root/build/lpv-server" --port 0 >"$work/server.log" 2>&1 &
server=$!
trap 'kill -TERM $server 2>/dev/null; wait $server 2>/dev/null; rm -rf "$work"' EXIT
port=""
for _ in $(seq 600); do
  port=$(head -1 "$work/server.log" | sed -n 's/.*:\([0-9][0-9]*\)$/\1/p')
  [ -n "$port" ] && break
  sleep 0.05
done
[ -n "$port" ] || { cat "$work/server.log"; exit 1; }
base="http://127.0.0.1:$port"
until curl -sf "$base/readyz" >/dev/null; do sleep 0.1; done
ms() { awk '{printf "%.1f ms", $1 * 1000}'; }
cache_bytes() { curl -s "$base/metrics" | awk '/^lpv_scene_cache_bytes/ {print $2}'; }

echo "== $(basename "$file"), ${size}x${size}, LPV on (the default request)"
upload=$(curl -s -o "$work/scene.json" -w '%{time_total}' -H 'Content-Type: application/octet-stream' \
  --data-binary @"$file" "$base/v1/scenes")
id=$(sed -n 's/.*"id":"\([0-9a-f]*\)".*/\1/p' "$work/scene.json")
[ -n "$id" ] || { echo "upload refused: $(cat "$work/scene.json")"; exit 1; }
echo "upload (parse, validate, store): $(echo "$upload" | ms)"
body="{\"scene\": \"$id\", \"output\": {\"width\": $size, \"height\": $size}}"
before=$(cache_bytes)
render() { curl -s -f -o /dev/null -w '%{time_total}\n' -H 'Content-Type: application/json' -d "$body" "$base/v1/render"; }
echo "first render (load, upload, render, PNG): $(render | ms)"
echo "cached scene: $(( ($(cache_bytes) - before) / 1024 )) KiB (host and device copies)"
for _ in 1 2 3 4 5; do render; done | sort -n | sed -n 3p | { read -r t; echo "warm render, median of 5: $(echo "$t" | ms)"; }
