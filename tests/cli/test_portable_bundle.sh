#!/usr/bin/env bash
# scripts/portable-bundle.sh as a user runs it: the archive unpacked at another path runs the
# renderer, loads its libraries from the bundle, finds the test files where it is, and runs a
# test suite from there. Usage: test_portable_bundle.sh SOURCE_DIR BUILD_DIR
set -u
source_dir="$1"
build_dir="$2"
. "$(dirname "$0")/script_checks.sh"
# Run from a bundle (its run.sh and origin at the top), there is no build machine to pack from.
if [ -e "$source_dir/origin" ] && [ -x "$source_dir/run.sh" ]; then
  echo "portable_bundle: skipped: this is a bundle; packing one needs the build machine's libraries" >&2
  exit 77
fi
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
haproxy=$(sed -n 's/^LPV_HAPROXY:[A-Z]*=//p' "$build_dir/CMakeCache.txt")
if [ -x "$haproxy" ]; then
  check "HAProxy comes with the bundle, and the scale-out test runs it from there" \
    bash -c "test -x '$here/bin/haproxy' && grep -rq --include=CTestTestfile.cmake 'LPV_HAPROXY=$here/bin/haproxy' '$here/build' &&
      '$here/run.sh' bin/haproxy -v | grep -q HAProxy"
fi
"$here/run.sh" ctest --test-dir build -R '^cli$' >"$work/ctest.txt" 2>&1
check "a suite runs from the bundle" grep -q "100% tests passed" "$work/ctest.txt"
finish || { cat "$work/pack.txt" "$work/render.txt" "$work/ctest.txt"; exit 1; }
