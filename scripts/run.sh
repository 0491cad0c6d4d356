#!/usr/bin/env bash
# The main job: install what is missing, build, and start lpv-server on 127.0.0.1:8080
# with the built-in scenes (cornell-box is the default). It prints a curl command that
# renders cornell-box.png; Ctrl-C stops it cleanly. Arguments go to lpv-server (try
# --help); LPV_SERVER_* environment variables work too.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/scripts/build.sh"
exec "$root/build/lpv-server" "$@"
