# shellcheck shell=bash disable=SC2154  # $corpus is set by the sourcing script
# Shared by cli_corpus.sh and server_corpus.sh (sourced, not run).
corpus_lib_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"

# The corpus files, sorted, one per line, relative to $corpus.
corpus_files() {
  (cd "$corpus" && find . -type f \( -name '*.gltf' -o -name '*.glb' \) | sed 's|^\./||' | LC_ALL=C sort)
}

# expected WHERE PATH: prints "render", "reject" or nothing (either is fine), from expectations.txt.
expected() {
  awk -v where="$1" -v path="$2" '
    /^[[:space:]]*(#|$)/ { next }
    $2 == path && ($3 == "" || $3 == where) { print $1; exit }' "$corpus_lib_dir/expectations.txt"
}

# sanitizer_report FILE: prints the lines of a sanitizer report in FILE (none: empty).
sanitizer_report() {
  grep -E -m 20 -e 'ERROR: (Address|Leak|UndefinedBehavior)Sanitizer' -e 'runtime error:' \
    -e '^SUMMARY: (Address|Leak|UndefinedBehavior)Sanitizer' -e '^    #[0-9]+ ' "$1"
}

# png_size FILE: prints "WIDTHxHEIGHT" of a PNG, or "not a PNG".
png_size() {
  if [ "$(od -An -tx1 -N8 "$1" 2>/dev/null | tr -d ' \n')" != "89504e470d0a1a0a" ]; then
    echo "not a PNG"
    return
  fi
  local w h
  w=$(od -An -tu1 -j16 -N4 "$1" | awk '{print $1*16777216 + $2*65536 + $3*256 + $4}')
  h=$(od -An -tu1 -j20 -N4 "$1" | awk '{print $1*16777216 + $2*65536 + $3*256 + $4}')
  echo "${w}x${h}"
}

# Bookkeeping: pass NAME WHAT, fail NAME WHY [DETAILS FILE], summary NOUN (what was counted).
rendered=0 rejected=0 failed=0
pass() {
  case "$2" in render*) rendered=$((rendered + 1)) ;; *) rejected=$((rejected + 1)) ;; esac
  printf '  ok   %-75s %s\n' "$1" "$2"
}
fail() {
  failed=$((failed + 1))
  printf 'FAIL   %-75s %s\n' "$1" "$2"
  [ -n "${3:-}" ] && [ -s "$3" ] || return 0
  local start='ERROR: (Address|Leak|UndefinedBehavior)Sanitizer|runtime error:'
  if grep -q -E "$start" "$3"; then  # a sanitizer report: from its start
    sed -n -E "/$start/,\$p" "$3" | head -n 80
  else
    tail -n 60 "$3"
  fi | sed 's/^/         | /'
}
# check_expectation WHERE NAME OUTCOME: fails when expectations.txt wants the other outcome.
check_expectation() {
  local want
  want=$(expected "$1" "$2")
  [ -z "$want" ] || [ "$want" = "$3" ] && return 0
  fail "$2" "expected to $want (tests/corpus/expectations.txt), but did $3"
  return 1
}
summary() {
  echo "$((rendered + rejected + failed)) $1: $rendered rendered, $rejected rejected cleanly, $failed failed"
  [ "$failed" -eq 0 ]
}
