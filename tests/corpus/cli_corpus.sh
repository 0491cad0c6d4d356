#!/usr/bin/env bash
# Every .gltf and .glb under CORPUS_DIR through `lpv-render --scene FILE` (64x64, the
# Vulkan validation layer on). Each file must either
#   - render: exit 0 and a 64x64 PNG, or
#   - be rejected: exit 3 with "lpv-render: FILE: <what is wrong>" on standard error,
# with no sanitizer report either way, within CORPUS_TIMEOUT seconds. Anything else (another
# exit status, a signal, a sanitizer report, a hang, validation messages) fails, and the
# file's output is printed. tests/corpus/expectations.txt pins the outcome of some files.
#   cli_corpus.sh LPV_RENDER CORPUS_DIR
# Environment: CORPUS_TIMEOUT (seconds per file, default 120).
set -u
bin="$(realpath "$1")"
corpus="$(realpath "$2")"
timeout_s=${CORPUS_TIMEOUT:-120}
# shellcheck source=tests/corpus/corpus_lib.sh
. "$(dirname "$0")/corpus_lib.sh"
[ -d "$corpus" ] || { echo "cli_corpus: no corpus at $corpus (install assimp-testmodels)"; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
# One pipeline cache and shader cache for the run: only the first render compiles pipelines.
export LPV_PIPELINE_CACHE="$work/pipeline-cache.bin" MESA_SHADER_CACHE_DIR="$work/mesa-cache"
echo '{"output": {"width": 64, "height": 64}}' >request.json
# The first render compiles the pipelines, which under the sanitizers with validation took most
# of the per-file timeout on a busy machine (2CylinderEngine, the first file, was killed as a
# hang at 120 s): a built-in scene compiles them first, so that each file's timeout measures
# its own work. Its outcome is the files' to judge: a broken binary fails every one of them.
timeout -k 10 600 "$bin" request.json -o warmup.png -q >/dev/null 2>&1

while IFS= read -r name; do
  file="$corpus/$name"
  rm -f out.png
  timeout -k 10 "$timeout_s" "$bin" request.json --scene "$file" -o out.png -q --validation >log.txt 2>&1
  rc=$?
  report=$(sanitizer_report log.txt)
  first_line=$(head -n 1 log.txt)
  if [ -n "$report" ]; then
    fail "$name" "sanitizer report (exit status $rc)" log.txt
  elif [ "$rc" -eq 124 ] || [ "$rc" -eq 137 ]; then
    fail "$name" "hang: still running after ${timeout_s}s" log.txt
  elif [ "$rc" -gt 128 ]; then
    fail "$name" "killed by signal $((rc - 128))" log.txt
  elif [ "$rc" -eq 0 ]; then
    size=$(png_size out.png)
    if [ "$size" != 64x64 ]; then
      fail "$name" "exit 0 but the output is $size, not a 64x64 PNG" log.txt
    elif check_expectation local "$name" render; then
      pass "$name" "rendered $size"
    fi
  elif [ "$rc" -eq 3 ]; then
    message=${first_line#"lpv-render: $file: "}
    if [ "$message" = "$first_line" ] || [ -z "$message" ]; then
      fail "$name" "exit 3 without 'lpv-render: $file: <message>'" log.txt
    elif [ -e out.png ]; then
      fail "$name" "rejected, but wrote out.png anyway" log.txt
    elif check_expectation local "$name" reject; then
      pass "$name" "rejected: $message"
    fi
  else
    fail "$name" "exit status $rc (0: rendered, 3: rejected)" log.txt
  fi
done < <(corpus_files)

summary files
