#!/usr/bin/env bash
# One build of this repository on two versions of lavapipe, taking turns on the same machine
# (`lpv-bench ab`, docs/perf-regression.md): what the driver alone changes (docs/lpv.md,
# "The driver").
#
#   bench/ab-drivers.sh VERSION_A VERSION_B [SUITE] [lpv-bench ab options ...]
#
#   VERSION_A, VERSION_B  versions of Debian's mesa-vulkan-drivers that apt can fetch
#                         (`apt-cache policy mesa-vulkan-drivers` lists them), e.g.
#                         22.3.6-1+deb12u2 (Debian 12) and 25.0.7-2~bpo12+1 (its backports)
#   SUITE                 a suite file or a name in bench/suites (default: lpv-512)
#
# Each version's package is fetched (`apt-get download`) and unpacked into
# $LPV_AB_DIR/mesa-VERSION (default LPV_AB_DIR: build-ab in the repository), and that side's
# lpv-bench runs with VK_ICD_FILENAMES naming its lavapipe; every other library (LLVM,
# libdrm) is the system's. The results go to $LPV_AB_DIR/drivers (ab.json, a.json, b.json,
# report.md); the report warns that the two sides' drivers differ, which is the point.
#
# Exit status: lpv-bench ab's (0 no regression, 1 a metric slower or an image changed in B,
# 2 bad input), 3 when a version cannot be fetched.
set -euo pipefail
. "$(dirname "$0")/ab_run.sh"
ab_need_two_arguments "$#"
root=$(cd "$(dirname "$0")/.." && pwd)
version_a=$1
version_b=$2
suite=${3:-lpv-512}
shift $(($# < 3 ? $# : 3))
work=${LPV_AB_DIR:-$root/build-ab}
[ -x "$root/build/lpv-bench" ] || "$root/scripts/build.sh" >&2

# Unpacks lavapipe of `version` once and writes the lpv-bench that runs on it; prints its path.
side() {
  local version=$1 dir="$work/mesa-$1"
  if [ ! -x "$dir/lpv-bench" ]; then
    rm -rf "$dir"
    mkdir -p "$dir/package"
    (cd "$dir/package" && apt-get download "mesa-vulkan-drivers=$version") >&2 || return 3
    dpkg-deb -x "$dir"/package/*.deb "$dir/root"
    local icd library
    icd=$(find "$dir/root" -name 'lvp_icd*.json' | head -n 1)
    library=$(find "$dir/root" -name libvulkan_lvp.so | head -n 1)
    [ -n "$icd" ] && [ -n "$library" ] || { echo "ab-drivers: no lavapipe in $version's package" >&2; return 3; }
    sed "s|\"library_path\": *\"[^\"]*\"|\"library_path\": \"$library\"|" "$icd" >"$dir/lvp_icd.json"
    printf '#!/bin/sh\nexport VK_ICD_FILENAMES="%s" VK_DRIVER_FILES="%s"\nexec "%s" "$@"\n' \
      "$dir/lvp_icd.json" "$dir/lvp_icd.json" "$root/build/lpv-bench" >"$dir/lpv-bench"
    chmod +x "$dir/lpv-bench"
  fi
  echo "$dir/lpv-bench"
}

a=$(side "$version_a") || { echo "ab-drivers: cannot fetch mesa-vulkan-drivers=$version_a" >&2; exit 3; }
b=$(side "$version_b") || { echo "ab-drivers: cannot fetch mesa-vulkan-drivers=$version_b" >&2; exit 3; }

ab_run "ab-drivers: mesa $version_a (A) against $version_b (B)" "$work/drivers" "$a" "$b" \
  "$(ab_suite_file "$suite" "$root/bench/suites")" "$@"
