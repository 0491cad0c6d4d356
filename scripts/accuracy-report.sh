#!/usr/bin/env bash
# Regenerates the accuracy-versus-time tables and plots of docs/accuracy.md: for every
# docs/accuracy/<scene>.sweep.json, lpv-bench sweep writes docs/accuracy/<scene>.{csv,svg,md,json},
# and the Markdown table replaces the block between the scene's markers in docs/accuracy.md.
#   scripts/accuracy-report.sh [SCENE...]     (default: every sweep file; builds first)
# On this project's 2-core lavapipe machine the 11 sweeps take about 8 minutes (the 8 of the
# default method about 3).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/scripts/build.sh" >/dev/null  # a no-op when the build is current
dir="$root/docs/accuracy"
doc="$root/docs/accuracy.md"

scenes=("$@")
if [ ${#scenes[@]} -eq 0 ]; then
  for f in "$dir"/*.sweep.json; do scenes+=("$(basename "$f" .sweep.json)"); done
fi

for scene in "${scenes[@]}"; do
  if [ ! -f "$dir/$scene.sweep.json" ]; then
    echo "accuracy-report: no sweep for '$scene' (docs/accuracy/$scene.sweep.json); have:" \
      "$(cd "$dir" && ls *.sweep.json | sed 's/\.sweep\.json$//' | tr '\n' ' ')" >&2
    exit 2
  fi
  echo "== $scene" >&2
  out=$(mktemp -d)
  "$root/build/lpv-bench" sweep "$dir/$scene.sweep.json" -o "$out" >/dev/null
  for ext in csv svg md json; do cp "$out/sweep.$ext" "$dir/$scene.$ext"; done
  rm -rf "$out"
  # The table between <!-- sweep:SCENE --> and <!-- /sweep:SCENE --> in docs/accuracy.md.
  awk -v scene="$scene" -v table="$dir/$scene.md" '
    $0 == "<!-- sweep:" scene " -->" { print; while ((getline line < table) > 0) print line; skip = 1; next }
    $0 == "<!-- /sweep:" scene " -->" { skip = 0 }
    !skip { print }' "$doc" >"$doc.tmp"
  mv "$doc.tmp" "$doc"
done
