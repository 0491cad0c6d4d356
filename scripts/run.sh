#!/usr/bin/env bash
# The main job: install what is missing, build, and start lpv-server on 127.0.0.1:8080
# with the built-in scenes (cornell-box is the default). It prints a curl command that
# renders cornell-box.png; Ctrl-C stops it cleanly. Arguments go to lpv-server (try
# --help); LPV_SERVER_* environment variables work too. Uploaded scenes and the pipeline
# cache are kept in data/ (git-ignored) unless a data directory is given.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/scripts/build.sh"
data_dir=()
if [ -z "${LPV_SERVER_DATA_DIR:-}" ] && [[ " $* " != *" --data-dir"* ]]; then data_dir=(--data-dir "$root/data"); fi
exec "$root/build/lpv-server" "${data_dir[@]}" "$@"
