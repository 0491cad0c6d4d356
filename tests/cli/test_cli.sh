#!/usr/bin/env bash
# lpv-render as a user runs it: files written, exit codes and messages for bad input.
set -u
bin="$(realpath "$1")"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
failures=0
passed=0

check() {  # check NAME CONDITION...
  local name="$1"; shift
  if "$@"; then passed=$((passed + 1)); else echo "FAIL: $name"; failures=$((failures + 1)); fi
}
# Runs lpv-render, keeping its exit status in $rc and its standard error in err.txt.
run() { "$bin" "$@" >out.txt 2>err.txt; rc=$?; }
u32be() { od -An -tu1 -j"$2" -N4 "$1" | awk '{print $1*16777216 + $2*65536 + $3*256 + $4}'; }

# No arguments: the default scene to cornell-box.png, 512x512, with validation on.
run --validation
check "default render exits 0" test "$rc" -eq 0
check "default render writes cornell-box.png" test -s cornell-box.png
check "PNG signature" test "$(od -An -tx1 -N8 cornell-box.png | tr -d ' ')" = "89504e470d0a1a0a"
check "PNG width 512" test "$(u32be cornell-box.png 16)" -eq 512
check "PNG height 512" test "$(u32be cornell-box.png 20)" -eq 512
check "summary names the device" grep -q "frame(s) on" err.txt

# A request file, EXR output and stats.
cat >req.json <<'JSON'
{"scene": "sun-courtyard", "output": {"width": 96, "height": 64, "view": "direct"}, "repeat": 3}
JSON
run req.json -o sun.exr --stats stats.json -q
check "request to EXR exits 0" test "$rc" -eq 0
check "EXR magic" test "$(od -An -tx1 -N4 sun.exr | tr -d ' ')" = "762f3101"
check "stats has passes" grep -q '"passes"' stats.json
check "stats counts 3 frames" grep -q '"frames": 3' stats.json
check "quiet prints nothing" test ! -s err.txt

run req.json -o sun.pfm -q
check "PFM header" test "$(head -c 3 sun.pfm | od -An -c | tr -d ' ')" = 'PF\n'

echo '{"output": {"format": "exr"}}' >exr.json
run exr.json -o wrong.png
check "format/extension clash exits 2" test "$rc" -eq 2
check "format/extension clash is explained" grep -q "does not match" err.txt
check "nothing written on a clash" test ! -e wrong.png

echo '{"output": {' >broken.json
run broken.json
check "malformed JSON exits 2" test "$rc" -eq 2
check "malformed JSON is explained" grep -q "invalid JSON" err.txt

echo '{"output": {"width": 0}}' >zero.json
run zero.json
check "bad field exits 2" test "$rc" -eq 2
check "bad field is named" grep -q "output.width" err.txt

echo '{"scene": "atlantis"}' >scene.json
run scene.json
check "unknown scene exits 2" test "$rc" -eq 2
check "unknown scene lists the built-ins" grep -q "cornell-box" err.txt

run --frobnicate
check "unknown option exits 2" test "$rc" -eq 2
check "unknown option shows usage" grep -q "usage: lpv-render" err.txt

run does-not-exist.json
check "missing request file exits 2" test "$rc" -eq 2

run --device no-such-gpu
check "unknown device exits 1" test "$rc" -eq 1
check "unknown device lists devices" grep -q "devices:" err.txt

run -o no-such-dir/out.png -q
check "unwritable output exits 1" test "$rc" -eq 1
check "unwritable output names the path" grep -q "no-such-dir" err.txt

run --list-scenes
check "list scenes" grep -q "^cornell-box " out.txt

run --help
check "help exits 0" test "$rc" -eq 0

echo "$passed passed, $failures failed"
test "$failures" -eq 0
