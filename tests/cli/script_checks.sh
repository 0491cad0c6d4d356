# What the command-line tests share (sourced): `check NAME CONDITION...` counts a condition
# and names it when it fails; `run ARGS...` runs the tool under test ($bin), keeping its exit
# status in $rc, its standard output in out.txt and its standard error in err.txt;
# `u32be FILE OFFSET` reads a big-endian 32-bit number (a PNG's size); `finish` prints the
# tally and is the script's exit status.
failures=0
passed=0

check() {  # check NAME CONDITION...
  local name="$1"; shift
  if "$@"; then passed=$((passed + 1)); else echo "FAIL: $name"; failures=$((failures + 1)); fi
}
run() { "$bin" "$@" >out.txt 2>err.txt; rc=$?; }
u32be() { od -An -tu1 -j"$2" -N4 "$1" | awk '{print $1*16777216 + $2*65536 + $3*256 + $4}'; }
finish() {
  echo "$passed passed, $failures failed"
  test "$failures" -eq 0
}
