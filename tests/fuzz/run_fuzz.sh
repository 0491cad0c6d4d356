#!/usr/bin/env bash
# Runs the glTF loader's libFuzzer target, seeded with every .gltf and .glb under SEED_DIR
# and in tests/fuzz/regressions/.
#   run_fuzz.sh [--fresh] FUZZER SEED_DIR WORK_DIR [libFuzzer options...]
# New inputs go to WORK_DIR/corpus, kept between runs so a longer run starts where the last
# one stopped; --fresh empties it and the artifacts first (with -seed=N and -runs=N the run
# is then repeatable). Crashes, timeouts and out-of-memory inputs go to WORK_DIR/artifacts/;
# reproduce one with: FUZZER WORK_DIR/artifacts/crash-... (see docs/testing.md).
# Exit status: 0 when the run found nothing, non-zero (with libFuzzer's report) otherwise.
set -euo pipefail
fresh=0
if [ "${1:-}" = --fresh ]; then fresh=1; shift; fi
fuzzer="$1" seed_dir="$2" work="$3"
shift 3
here="$(cd "$(dirname "$0")" && pwd)"
[ -d "$seed_dir" ] || { echo "run_fuzz: no seed directory $seed_dir (install assimp-testmodels)" >&2; exit 1; }
[ "$fresh" -eq 0 ] || rm -rf "$work/corpus" "$work/artifacts"
mkdir -p "$work/corpus" "$work/artifacts"
seeds=$(mktemp -d)
trap 'rm -rf "$seeds"' EXIT
# libFuzzer writes new inputs into its first corpus directory: never the installed seeds.
count=0
while IFS= read -r -d '' file; do
  relative="${file#"$seed_dir"/}"
  cp "$file" "$seeds/${relative//\//_}"
  count=$((count + 1))
done < <(find "$seed_dir" -type f \( -name '*.gltf' -o -name '*.glb' \) -print0)
[ "$count" -gt 0 ] || { echo "run_fuzz: no .gltf or .glb under $seed_dir" >&2; exit 1; }
# Inputs that once broke the loader (tests/fuzz/regressions/README.md): tried first, like every seed.
for file in "$here"/regressions/*.gltf "$here"/regressions/*.glb; do
  if [ -f "$file" ]; then
    cp "$file" "$seeds/regression_$(basename "$file")"
    count=$((count + 1))
  fi
done
echo "run_fuzz: $count seeds from $seed_dir and $here/regressions; corpus $work/corpus; artifacts $work/artifacts/"
"$fuzzer" -dict="$here/gltf.dict" -artifact_prefix="$work/artifacts/" -print_final_stats=1 "$@" \
  "$work/corpus" "$seeds"
