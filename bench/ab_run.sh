# What bench/ab-commits.sh and bench/ab-drivers.sh share (sourced, not run): the usage on too
# few arguments, the suite argument and the `lpv-bench ab` run with its report, so the two
# read their arguments and report alike.

# Prints the header comment of the script that sources this (its usage) and exits 2 unless
# it was given at least two arguments:  ab_need_two_arguments "$#"
ab_need_two_arguments() {
  if [ "$1" -lt 2 ]; then
    sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2
    exit 2
  fi
}

# The suite file of SUITE: a path as given (anything with a '/' or ending in .json), else
# the suite of that name in DIR:  ab_suite_file SUITE DIR
ab_suite_file() {
  case "$1" in
    */* | *.json) realpath "$1" ;;
    *) echo "$2/$1.json" ;;
  esac
}

# Runs B's lpv-bench ab with A taking turns, results and report.md into RESULTS, and exits
# with its status (0 no regression, 1 one found, 2 bad input), saying so with WHAT:
#   ab_run WHAT RESULTS A_BENCH B_BENCH SUITE_FILE [lpv-bench ab options ...]
ab_run() {
  local what=$1 results=$2 a=$3 b=$4 suite_file=$5
  shift 5
  mkdir -p "$results"
  local status=0
  "$b" ab --a "$a" --b "$b" "$suite_file" -o "$results" --report "$results/report.md" "$@" || status=$?
  echo "$what: exit status $status; results in $results" >&2
  exit "$status"
}
