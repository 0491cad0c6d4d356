#!/usr/bin/env bash
# lpv-bench run, compare and ab as a regression job runs them, on the quick suite:
# results that match bench/results.schema.json, reports, exit statuses, a changed image
# caught with unchanged times, the same suite through a server, and bad input.
#   test_bench_regression.sh LPV_BENCH LPV_SERVER CHECK_JSON_SCHEMA BENCH_DIR
set -u
. "$(dirname "$0")/../cli/script_checks.sh"
bin="$(realpath "$1")"
server_bin="$(realpath "$2")"
check_schema="$(realpath "$3")"
schema="$(realpath "$4")/results.schema.json"
quick="$(realpath "$4")/suites/quick.json"
work=$(mktemp -d)
server_pid=""
trap '[ -n "$server_pid" ] && kill "$server_pid" 2>/dev/null; rm -rf "$work"' EXIT
cd "$work" || exit 1
valid() { "$check_schema" "$schema" "$1" || { cat err.txt; return 1; }; }

# --- run, in this process; the round trip through the lpv-server beside lpv-bench -------
run run quick -o base.json --report base.md --label base --server-binary "$server_bin"
check "run exits 0" test "$rc" -eq 0
check "results match the schema" valid base.json
check "every case ran" test "$(grep -c '"status": "ok"' base.json)" -eq 3
check "the round trip was timed" grep -q '"round_trip_ms"' base.json
check "per-pass metrics" grep -q '"pass.propagate"' base.json
check "3 samples each" grep -q '"n": 3' base.json
check "the build's commit" grep -q '"commit": "' base.json
check "summary table on standard output" grep -q "cornell-box/lpv-8-i2 *gpu_ms" out.txt
check "the summary says how steady the machine was" grep -q "^machine noise: CPU probe .* ms, scatter" out.txt
check "results carry the noise probe" grep -q '"name": "probe_ms"' base.json
check "Markdown report" grep -q "^| cornell-box/direct | gpu_ms |" base.md
check "progress on standard error" grep -q "quick" err.txt

run run "$quick" -q --no-server --repetitions 2 --warmup 0 --label override -o skipped.json
check "run without a server exits 0" test "$rc" -eq 0
check "the round trip is skipped with its reason" grep -q '"reason": "--no-server' skipped.json
check "--repetitions overrides the suite" grep -q '"repetitions": 2' skipped.json
check "quiet prints nothing" test ! -s out.txt

# --- compare -------------------------------------------------------------------------
# These checks are about the comparison, not the machine: --max-probe-spread 1000 judges the
# times however noisy the CI runner was (the noisy machine is checked after ab below).
run compare base.json base.json -o same.json --report same.md --max-probe-spread 1000
check "compare of a run with itself exits 0" test "$rc" -eq 0
check "no regression said" grep -q "no regression" out.txt
check "comparison JSON" grep -q '"regression": false' same.json
check "too few repetitions are warned about" grep -q "cannot show any difference" out.txt
run compare base.json base.json -q --max-probe-spread 1000
check "-q: the verdict alone, one line" test "$(cat out.txt)" = "no regression"

# The same suite with one image made brighter: same work, same times, another image.
sed 's/"output": {"width": 64, "height": 64}, "lpv": {"enabled": false}/"output": {"width": 64, "height": 64, "exposure": 1}, "lpv": {"enabled": false}/' \
  "$quick" >brighter.json
check "the test edited the suite" grep -q '"exposure": 1' brighter.json
run run brighter.json -q --no-server -o brighter-results.json
run compare base.json brighter-results.json --report changed.md
check "a changed image exits 1" test "$rc" -eq 1
check "the changed image is named" grep -q "image .*changed: thumbnails differ" out.txt
check "REGRESSION said" grep -q "REGRESSION" out.txt
check "report says regression" grep -q "## Performance: regression" changed.md

# --- the same suite through a running server (--url) ---------------------------------
"$server_bin" --port 0 >server.log 2>&1 &
server_pid=$!
for _ in $(seq 1 600); do grep -q "listening on" server.log && break; sleep 0.1; done
url=$(sed -n 's/^lpv-server listening on //p' server.log | head -1)
for _ in $(seq 1 600); do curl -sf "$url/readyz" >/dev/null 2>&1 && break; sleep 0.1; done
run run quick --url "$url" -q -o http.json
check "run --url exits 0" test "$rc" -eq 0
check "http results match the schema" valid http.json
check "mode http" grep -q '"mode": "http"' http.json
check "every case has a round trip" test "$(grep -c '"round_trip_ms"' http.json)" -eq 3
run compare base.json http.json
check "results of both modes compare" test "$rc" -ne 2
check "the images through the server are the same images" test "$(grep -c 'image .*changed' out.txt)" -eq 0
check "the modes' difference is warned about" grep -q "different modes (in_process and http)" out.txt
# --jobs: the cases spread over connections (bench/fan-out.sh does it over replicas); the
# results are the serial run's cases, in order, with the same images.
run run quick --url "$url" --jobs 3 -q -o fanned.json
check "run --jobs 3 exits 0" test "$rc" -eq 0
check "fanned results match the schema" valid fanned.json
check "the same cases in the same order" \
  test "$(grep -o '"name": "[^"]*"' http.json)" = "$(grep -o '"name": "[^"]*"' fanned.json)"
check "the same images" test "$(grep -o '"sha256": "[0-9a-f]*"' http.json)" = "$(grep -o '"sha256": "[0-9a-f]*"' fanned.json)"
check "every image there" test "$(grep -c '"sha256"' fanned.json)" -eq 3
# sweep --url --jobs 2: the server sweeps in two parts at once; the rows are a local sweep's,
# settings and errors (the times are the server's).
cat >sweep.json <<'JSON'
{"base": {"output": {"width": 32, "height": 24}}, "parameters": {"grid": [8, 12], "occlusion": [true, false]},
 "reference": {"samples": 4}}
JSON
run sweep sweep.json -q -o local-sweep
run sweep sweep.json --url "$url" --jobs 2 -q -o served-sweep
check "sweep --url --jobs 2 exits 0" test "$rc" -eq 0
for f in sweep.json sweep.csv sweep.md sweep.svg; do check "the served sweep writes $f" test -s "served-sweep/$f"; done
untimed_columns() {  # the CSV without its time, frame and front columns
  awk -F, 'NR == 1 { for (c = 1; c <= NF; ++c) keep[c] = $c !~ /gpu_ms|wall_ms|frames|pareto/ }
           { line = ""; for (c = 1; c <= NF; ++c) if (keep[c]) line = line $c ","; print line }' "$1"
}
check "the served sweep has the 5 rows" test "$(wc -l <served-sweep/sweep.csv)" -eq 6
check "the served sweep's rows are the local one's, in its order" \
  test "$(untimed_columns local-sweep/sweep.csv)" = "$(untimed_columns served-sweep/sweep.csv)"
check "its front is marked" grep -q '"pareto": true' served-sweep/sweep.json
kill "$server_pid"; wait "$server_pid" 2>/dev/null; server_pid=""

# --- ab: this build against itself, render by render --------------------------------------
run ab --a "$bin" --b "$bin" "$quick" --rounds 3 --no-server -o ab --report ab.md
# Never a regression; "inconclusive" (4) when the machine was too noisy to judge, as a busy CI
# runner may be.
check "ab of a build with itself is no regression (0, or 4: noisy machine)" test "$rc" -eq 0 -o "$rc" -eq 4
[ "$rc" -eq 4 ] && check "an inconclusive ab says why" grep -q "INCONCLUSIVE: noisy machine; the CPU probe" out.txt
# No probe is that steady: inconclusive, whatever the machine, with exit 4 and the reason.
run compare ab/a.json ab/b.json -q --max-probe-spread 0
check "a noisy machine exits 4" test "$rc" -eq 4
check "a noisy machine says so in one line, each run's reason" grep -q "^INCONCLUSIVE: noisy machine; A: the CPU probe's times scatter by .*; B: the CPU probe.*rerun on a quieter machine$" out.txt
for f in ab.json a.json b.json; do check "ab writes $f" test -s "ab/$f"; done
check "ab's results match the schema" valid ab/a.json
check "ab's B results match the schema" valid ab/b.json
check "3 pairs" grep -q '"repetitions": 3' ab/b.json
check "labelled B" grep -q '"label": "B"' ab/b.json
check "ab is paired" grep -q '"paired": true' ab/ab.json
check "ab report" grep -q "Wilcoxon" ab.md
run ab --a "$bin" --b /bin/true "$quick" -q
check "a build that is no worker exits 1" test "$rc" -eq 1
check "the build that is no worker is named" grep -q "build B (/bin/true) did not start as a worker" err.txt

# The worker that ab talks to: one JSON line per command, errors as answers.
printf 'time 0\nimage 1\nfly 0\ntime 9\ntime 2\n' | "$bin" worker "$quick" --no-server >worker.txt 2>err.txt
check "worker exits 0 at the end of its input" test "$?" -eq 0
check "worker greets first" grep -q '^{"lpv_bench_worker":1' <(head -1 worker.txt)
check "worker times a case" grep -q '^{"metrics":\[\["gpu_ms",' worker.txt
check "worker fingerprints a case" grep -q '^{"image":{"height":64' worker.txt
check "worker refuses a bad command" grep -q "not a command: 'fly 0'" worker.txt
check "worker refuses a case out of range" grep -q "not a command: 'time 9'" worker.txt
check "worker says why there is no round trip" grep -q '"error":"--no-server' worker.txt

# --- bad input: exit 2, the problem named ----------------------------------------------
echo '{"suite": "bad", "version": 1, "cases": [{"name": "a", "request": {"lpv": {"grid": 0}}}]}' >bad.json
run run bad.json -q
check "a bad suite exits 2" test "$rc" -eq 2
check "a bad suite names the field" grep -q "cases\[0\].request.lpv.grid: must be" err.txt
check "nothing written for a bad suite" test ! -e results.json
run run no-such-suite
check "an unknown suite exits 2" test "$rc" -eq 2
check "an unknown suite is named" grep -q "no suite 'no-such-suite'" err.txt
run compare base.json bad.json
check "a suite is not a results file: exit 2" test "$rc" -eq 2
check "a non-results file is named" grep -q "bad results file .*bad.json: format" err.txt
run compare base.json
check "compare needs two files" test "$rc" -eq 2
run run quick --alpha 0.1
check "an option of another command exits 2" test "$rc" -eq 2
check "the option is named" grep -q "option --alpha is not for run" err.txt
run compare base.json base.json --min-effect lots
check "a bad number exits 2" test "$rc" -eq 2
run ab --a "$bin" quick
check "ab needs both builds" test "$rc" -eq 2
run ab --a "$bin" --b ./nothing quick
check "ab names a missing build" grep -q "\-\-b: './nothing' is not an executable file" err.txt
run run quick --url ftp://example.com -q
check "a bad URL exits 2" test "$rc" -eq 2
run run quick --jobs 2 -q
check "--jobs without --url exits 2" test "$rc" -eq 2
check "--jobs names what it needs" grep -q "\-\-jobs needs --url" err.txt

finish
