#!/usr/bin/env bash
# scripts/portable-bundle.sh as a user runs it: the archive unpacked at another path runs the
# renderer, loads its libraries from the bundle, finds the test files where it is, and runs a
# test suite from there. Usage: test_portable_bundle.sh SOURCE_DIR BUILD_DIR
set -u
source_dir="$1"
build_dir="$2"
. "$(dirname "$0")/script_checks.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

XZ_OPT=-0 "$source_dir/scripts/portable-bundle.sh" "$work/lpv.tar.xz" "$build_dir" >"$work/pack.txt" 2>&1
check "the bundle is packed" test $? -eq 0 -a -s "$work/lpv.tar.xz"
mkdir "$work/elsewhere"
tar -xJf "$work/lpv.tar.xz" -C "$work/elsewhere"
here="$work/elsewhere"

"$here/run.sh" build/lpv-render -q -o "$work/frame.png" >/dev/null 2>"$work/render.txt"
check "run.sh renders a frame" test $? -eq 0 -a -s "$work/frame.png"
check "the frame is a 512-wide PNG" test "$(u32be "$work/frame.png" 16)" -eq 512
"$here/run.sh" ldd build/lpv-server >"$work/ldd.txt" 2>&1
check "httplib comes from the bundle" grep -q "libcpp-httplib.so.* => $here/lib/" "$work/ldd.txt"
check "the Vulkan loader comes from the bundle" grep -q "libvulkan.so.1 => $here/lib/" "$work/ldd.txt"
check "the validation layer is in the bundle" test -s "$here/lib/libVkLayer_khronos_validation.so" -a \
  -s "$here/layers/VkLayer_khronos_validation.json"
check "the CTest files name the bundle, not the build" \
  bash -c "! grep -rq --include=CTestTestfile.cmake '$build_dir' '$here/build' && grep -q '$here/build' '$here/build/CTestTestfile.cmake'"
"$here/run.sh" ctest --test-dir build -R '^cli$' >"$work/ctest.txt" 2>&1
check "a suite runs from the bundle" grep -q "100% tests passed" "$work/ctest.txt"
finish || { cat "$work/pack.txt" "$work/render.txt" "$work/ctest.txt"; exit 1; }
