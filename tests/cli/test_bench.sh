#!/usr/bin/env bash
# lpv-bench as a user runs it: the files of a sweep and of a diff, exit codes and messages.
#   test_bench.sh LPV_BENCH SUITES_DIR
set -u
. "$(dirname "$0")/script_checks.sh"
bin="$(realpath "$1")"
suites="$(realpath "$2")"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

cat >sweep.json <<'JSON'
{"base": {"output": {"width": 48, "height": 32}}, "parameters": {"grid": [8, 16], "occlusion": [true, false]},
 "reference": {"samples": 8}}
JSON
run sweep sweep.json -o result
check "sweep exits 0" test "$rc" -eq 0
for f in sweep.json sweep.csv sweep.md sweep.svg; do check "sweep writes $f" test -s "result/$f"; done
check "CSV: header and 5 rows" test "$(wc -l <result/sweep.csv)" -eq 6
check "Markdown: 5 table rows" test "$(grep -c '^| o' result/sweep.md)" -eq 5
check "Markdown on standard output" grep -q "Pareto" out.txt
check "SVG document" grep -q "</svg>" result/sweep.svg
check "JSON names the reference's samples" grep -q '"samples": 8' result/sweep.json
check "progress on standard error, errors then timing" grep -q "timing" err.txt
frames_column=$(head -1 result/sweep.csv | tr ',' '\n' | grep -n '^frames$' | cut -d: -f1)
check "CSV: every row timed over 3 frames (the default repeat)" \
  test "$(cut -d, -f"$frames_column" result/sweep.csv | tail -n +2 | sort -u | tr -d '\r')" = 3

cat >diff.json <<'JSON'
{"base": {"output": {"width": 40, "height": 24}, "lpv": {"grid": 8}}, "against": {"lpv": {"grid": 16}}}
JSON
run diff diff.json -o d -q
check "diff exits 0" test "$rc" -eq 0
for f in base.png other.png difference.png base.exr other.exr compare.json; do check "diff writes $f" test -s "d/$f"; done
check "difference.png is 40 wide" test "$(u32be d/difference.png 16)" -eq 40
check "difference.png is 24 high" test "$(u32be d/difference.png 20)" -eq 24
check "compare.json has metrics" grep -q '"rmse"' d/compare.json
check "quiet prints nothing" test ! -s out.txt

# budget: the lone plane (its planner skips the LPV: every frame is cheap), small and noisy,
# for the files and their shape; how well budgets are met is docs/budget.md's full run.
run budget lone-plane --size 32 --samples 4 -o b
check "budget exits 0" test "$rc" -eq 0
for f in budget.json budget.md; do check "budget writes $f" test -s "b/$f"; done
check "budget: four budgets of the scene (T/2, T, 2T, 4T)" test "$(grep -c '"scene": "lone-plane"' b/budget.json)" -eq 4
check "budget: each with its choice, prediction and time" \
  test "$(grep -c -e '"chosen":' -e '"predicted_ms":' -e '"actual_ms":' b/budget.json)" -eq 12
check "budget: the summary counts the budgets met" grep -q "^- frame time within 1.1x the budget: [0-4] of 4" b/budget.md
check "budget: a table row per budget" test "$(grep -c '^| lone-plane |' b/budget.md)" -eq 4
run budget atlantis -o nowhere
check "budget of an unknown scene exits 2" test "$rc" -eq 2
check "budget of an unknown scene names it" grep -q "unknown scene 'atlantis'" err.txt
check "nothing written for an unknown scene" test ! -e nowhere
run budget --size 8
check "budget --size below 16 exits 2" test "$rc" -eq 2

echo '{"base": {}, "parameters": {"grid": [0]}}' >bad.json
run sweep bad.json -o bad
check "bad request exits 2" test "$rc" -eq 2
check "bad request names the field" grep -q "parameters.grid\[0\]" err.txt
check "nothing written for a bad request" test ! -e bad
run frobnicate sweep.json
check "unknown command exits 2" test "$rc" -eq 2
check "unknown command is named" grep -q "unknown command 'frobnicate'" err.txt
pointer_not_help() { test "$(tail -n 1 err.txt)" = "Try 'lpv-bench --help'." && ! grep -q "usage:" err.txt; }
check "unknown command: a pointer to --help, not the help" pointer_not_help
run sweep missing.json
check "missing file exits 2" test "$rc" -eq 2
run --help
check "help exits 0" test "$rc" -eq 0
check "help shows usage" grep -q "usage: lpv-bench sweep" out.txt
for suite in "$suites"/*.json; do
  name="$(basename "$suite" .json)"
  check "help lists the suite $name" grep -q "^suites in bench/suites: .*\b$name\b" out.txt
done

finish
