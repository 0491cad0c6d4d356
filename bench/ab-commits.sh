#!/usr/bin/env bash
# A nightly performance job in one command: builds two commits of this repository side by
# side (Release, only lpv-bench and lpv-server) and runs `lpv-bench ab` on them, so that the
# two builds take turns on the same machine (docs/perf-regression.md).
#
#   bench/ab-commits.sh BASELINE CANDIDATE [SUITE] [lpv-bench ab options ...]
#
#   BASELINE, CANDIDATE  commits (anything git rev-parse takes: a hash, origin/main, HEAD~1)
#   SUITE                a suite file or a name in the candidate's bench/suites (default: default)
#
# Environment: LPV_AB_DIR, the work directory (default: build-ab in the repository): it keeps
# a worktree and a build per commit, so that a later run with the same commits rebuilds
# nothing; the results go to $LPV_AB_DIR/results (ab.json, a.json, b.json, report.md).
#
# Exit status: lpv-bench ab's (0 no regression, 1 a metric slower, an image changed or a case
# failing in the candidate, 2 bad input), 3 when a commit does not build.
set -euo pipefail
. "$(dirname "$0")/ab_run.sh"
ab_need_two_arguments "$#"
root=$(git -C "$(dirname "$0")" rev-parse --show-toplevel)
baseline=$(git -C "$root" rev-parse --verify "$1^{commit}")
candidate=$(git -C "$root" rev-parse --verify "$2^{commit}")
suite=${3:-default}
shift $(($# < 3 ? $# : 3))
work=${LPV_AB_DIR:-$root/build-ab}
mkdir -p "$work"

# Checks out `commit` in its own worktree and builds what the A/B run needs there; prints the
# build directory. One build serves both sides when the commits are the same (an A/A run,
# which measures the machine's noise).
build() {
  local commit=$1 src="$work/src-$1" out="$work/build-$1"
  if [ ! -d "$src" ]; then
    git -C "$root" worktree add --detach "$src" "$commit" >&2
  fi
  cmake -S "$src" -B "$out" -G Ninja -DCMAKE_BUILD_TYPE=Release -DLPV_BUILD_TESTS=OFF >&2 &&
    cmake --build "$out" --target lpv-bench lpv-server >&2 || return 3
  echo "$out"
}

a=$(build "$baseline") || { echo "ab-commits: $baseline does not build" >&2; exit 3; }
b=$(build "$candidate") || { echo "ab-commits: $candidate does not build" >&2; exit 3; }

# Both builds run the candidate's suite, read once: the cases a change adds are measured too
# (a case the baseline cannot run is reported as failed in the baseline, not as a regression).
suite_file=$(ab_suite_file "$suite" "$work/src-$candidate/bench/suites")
LPV_BENCH_COMMIT="" ab_run "ab-commits: $baseline (A) against $candidate (B)" "$work/results" "$a/lpv-bench" \
  "$b/lpv-bench" "$suite_file" "$@"
