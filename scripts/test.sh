#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test (CTest) on lavapipe with the
# Vulkan validation layer on. Arguments are passed to ctest (e.g. -R renderer, -L stress).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/scripts/build.sh"
cd "$root/build"
ctest --output-on-failure --timeout 600 "$@"
