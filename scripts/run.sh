#!/usr/bin/env bash
# The main job: install what is missing, build, and render the embedded default scene
# (cornell-box) to cornell-box.png in the current directory, with its timing stats.
# Arguments are passed to lpv-render (try --help).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/scripts/build.sh"
exec "$root/build/lpv-render" "$@"
