#!/usr/bin/env bash
# The README's test command, RUNS times in a row (default 5), with one core kept busy the
# whole time, to find tests that assume the machine's speed (issue 42). One log per run in
# OUT (default build/load-runs/), then a line per test: how many runs it passed.
#   scripts/test-under-load.sh [RUNS [OUT]]
set -u
root="$(cd "$(dirname "$0")/.." && pwd)"
runs=${1:-5}
out=${2:-$root/build/load-runs}
mkdir -p "$out"
sh -c 'while :; do :; done' &
busy=$!
trap 'kill $busy' EXIT
for i in $(seq 1 "$runs"); do
  start=$SECONDS
  "$root/scripts/test.sh" >"$out/run-$i.log" 2>&1
  echo "run $i: exit $?, $((SECONDS - start)) s; test time $(grep -h 'Total Test time' "$out/run-$i.log" | grep -o '[0-9.]* sec' | tr '\n' ' ')"
done
# "name: passed/runs", each stage's tests counted together.
grep -h -E '^ *[0-9]+/[0-9]+ Test +#[0-9]+: ' "$out"/run-*.log |
  sed -E 's/^.*Test +#[0-9]+: ([A-Za-z0-9_]+) .*/\1 &/' |
  awk '{ seen[$1]++; if ($0 ~ / Passed /) passed[$1]++ } END { for (t in seen) printf "%s: %d/%d\n", t, passed[t], seen[t] }' | sort
