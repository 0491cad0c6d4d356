#!/usr/bin/env bash
# lpv-render as a user runs it: files written, exit codes and messages for bad input.
#   test_cli.sh LPV_RENDER [GLTF_CORPUS_DIR]
set -u
. "$(dirname "$0")/script_checks.sh"
bin="$(realpath "$1")"
corpus="$(realpath "${2:-/usr/share/assimp/models/glTF2}")"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

# No arguments: the default scene to cornell-box.png, 512x512, with validation on.
run --validation
check "default render exits 0" test "$rc" -eq 0
check "default render writes cornell-box.png" test -s cornell-box.png
check "PNG signature" test "$(od -An -tx1 -N8 cornell-box.png | tr -d ' ')" = "89504e470d0a1a0a"
check "PNG width 512" test "$(u32be cornell-box.png 16)" -eq 512
check "PNG height 512" test "$(u32be cornell-box.png 20)" -eq 512
check "summary names the device" grep -q "1 frame on" err.txt

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

# Bad usage: one line naming the problem and a pointer to --help, not the whole help.
one_line_and_pointer() {  # err.txt: "lpv-render: <problem>", then "Try 'lpv-render --help'."
  test "$(wc -l <err.txt)" -eq 2 && grep -q "^lpv-render: ." err.txt &&
    test "$(tail -n 1 err.txt)" = "Try 'lpv-render --help'." && ! grep -q "usage:" err.txt
}
run --frobnicate
check "unknown option exits 2" test "$rc" -eq 2
check "unknown option is named" grep -q "^lpv-render: unknown option --frobnicate$" err.txt
check "unknown option: one line and a pointer" one_line_and_pointer

run does-not-exist.json
check "missing request file exits 2" test "$rc" -eq 2
check "missing request file is named" grep -q "^lpv-render: .*'does-not-exist.json': no such file" err.txt
check "missing request file: one line and a pointer" one_line_and_pointer

run -o
check "-o without a file exits 2" test "$rc" -eq 2
check "-o without a file is explained" grep -q "^lpv-render: option -o needs a value" err.txt
check "-o without a file: one line and a pointer" one_line_and_pointer
run -o -q
check "-o followed by an option exits 2" test "$rc" -eq 2
check "-o followed by an option is explained" grep -q "option -o needs a value" err.txt
check "-o followed by an option writes no file named -q" test ! -e ./-q

# An extension no format has is an error naming those it can write, not a PNG under that name.
run -o out.jpg
check "-o out.jpg exits 2" test "$rc" -eq 2
check "-o out.jpg names the formats" grep -q "'out.jpg'.*\.png, \.exr and \.pfm" err.txt
check "-o out.jpg: one line and a pointer" one_line_and_pointer
check "nothing written for out.jpg" test ! -e out.jpg
echo '{"output": {"width": 32, "height": 24}}' >tiny.json
run tiny.json -o upper.PNG -q
check "-o upper.PNG (any case) exits 0" test "$rc" -eq 0
check "-o upper.PNG writes a PNG" test "$(od -An -tx1 -N4 upper.PNG | tr -d ' ')" = "89504e47"

# Progress ("frame 2/3 gather") on a terminal, erased when done; never in a log.
echo '{"output": {"width": 32, "height": 32}, "repeat": 3}' >frames.json
script -qefc "'$bin' frames.json -o frames.png" /dev/null >tty.txt 2>&1
check "a render on a terminal exits 0" test $? -eq 0
check "a render on a terminal shows its progress" grep -q "frame 3/3 gather" tty.txt
check "the progress is erased before the summary" grep -q "$(printf '\033\\[K')frames.png: 32x32 final, 3 frames on" tty.txt
run frames.json -o frames.png
check "no progress when standard error is a file" test "$(grep -c "frame [0-9]/3" err.txt)" -eq 0
check "the summary still follows" grep -q "3 frames on" err.txt

# The propagation's column length changes how the work is cut, not the image.
echo '{"output": {"width": 64, "height": 64, "format": "pfm"}, "lpv": {"transfer": "sharpened", "grid": [13, 10, 9]}, "plan": "exact"}' >col.json
run col.json -o col-default.pfm -q
run col.json -o col-2.pfm -q --propagate-column 2
check "--propagate-column 2 exits 0" test "$rc" -eq 0
check "--propagate-column 2 gives the same image" cmp -s col-default.pfm col-2.pfm
run --propagate-column 0
check "--propagate-column 0 exits 2" test "$rc" -eq 2
check "--propagate-column 0 is explained" grep -q "1 to 64" err.txt

run --device no-such-gpu
check "unknown device exits 1" test "$rc" -eq 1
check "unknown device lists devices" grep -q "devices:" err.txt

run -o no-such-dir/out.png -q
check "unwritable output exits 1" test "$rc" -eq 1
check "unwritable output names the path" grep -q "no-such-dir" err.txt

# --scene NAME: a built-in scene instead of the request's.
echo '{"output": {"width": 80, "height": 48}}' >small.json
run small.json --scene sun-courtyard -q
check "--scene NAME exits 0" test "$rc" -eq 0
check "--scene NAME names the output" test -s sun-courtyard.png

# --scene FILE: a glTF file (binary, embedded data), output named after it.
box="$corpus/BoxTextured-glTF-Binary/BoxTextured.glb"
run small.json --scene "$box" -q
check "--scene FILE.glb exits 0" test "$rc" -eq 0
check "--scene FILE.glb writes BoxTextured.png" test -s BoxTextured.png
check "--scene FILE.glb PNG width 80" test "$(u32be BoxTextured.png 16)" -eq 80
check "--scene FILE.glb PNG height 48" test "$(u32be BoxTextured.png 20)" -eq 48
# A .gltf whose buffer and texture are files next to it.
run small.json --scene "$corpus/BoxTextured-glTF/BoxTextured.gltf" -o external.png -q
check "--scene FILE.gltf with external files exits 0" test "$rc" -eq 0
check "--scene FILE.gltf with external files writes the PNG" test -s external.png

# Files that cannot be loaded: exit 3, "lpv-render: FILE: what is wrong", nothing written.
head -c 200 "$box" >truncated.glb
run --scene truncated.glb -o truncated.png
check "truncated .glb exits 3" test "$rc" -eq 3
check "truncated .glb message names the file" grep -q "^lpv-render: truncated.glb: ." err.txt
check "nothing written for a bad file" test ! -e truncated.png
echo '{"asset": {"version": "2.0"}, "meshes": [' >broken.gltf
run --scene broken.gltf
check "malformed .gltf exits 3" test "$rc" -eq 3
check "malformed .gltf message names the file" grep -q "^lpv-render: broken.gltf: ." err.txt
run --scene "$corpus/IndexOutOfRange/IndexOutOfRange.gltf"
check "indices out of range exit 3" test "$rc" -eq 3
check "indices out of range are explained" grep -qi "index\|indices" err.txt
run --scene "$corpus/MissingBin/BoxTextured.gltf"
check "missing .bin exits 3" test "$rc" -eq 3
check "missing .bin is named" grep -q "BoxTextured0.bin" err.txt
run --scene "$corpus/draco/2CylinderEngine.gltf"
check "a Draco-compressed file exits 3" test "$rc" -eq 3
check "a Draco-compressed file names the extension" \
  grep -q "required extension KHR_draco_mesh_compression is not supported" err.txt
# A glTF 1.0 file of our own: the corpus's (glTF/TwoBoxes) lies outside the glTF2 folder
# that the portable bundle carries.
printf '%s' '{"asset": {"version": "1.0"}, "scenes": {"s": {"nodes": []}}, "scene": "s"}' >gltf1.gltf
run --scene gltf1.gltf
check "a glTF 1.0 file exits 3" test "$rc" -eq 3
check "a glTF 1.0 file is named as such" grep -q "glTF 1.0 is not supported (2.0 only)" err.txt
run --scene no-such-model.glb
check "missing scene file exits 3" test "$rc" -eq 3
check "missing scene file is explained" grep -q "^lpv-render: no-such-model.glb: .*no such file" err.txt

# --scene FILE and a request that names a scene, or --scene twice: bad usage.
run scene.json --scene "$box"
check "request scene and --scene FILE exit 2" test "$rc" -eq 2
check "request scene and --scene FILE are explained" grep -q "give one of them" err.txt
run --scene cornell-box --scene "$box"
check "--scene twice exits 2" test "$rc" -eq 2

run --list-scenes
check "list scenes" grep -q "^cornell-box " out.txt

run --help
check "help exits 0" test "$rc" -eq 0
check "help documents --scene FILE" grep -q -- "--scene FILE" out.txt
check "help documents exit status 3" grep -q "^  3 " out.txt

finish
