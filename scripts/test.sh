#!/usr/bin/env bash
# Installs what is missing, then runs the two test stages (docs/testing.md), both built with
# warnings as errors (LPV_WERROR), so no warning lands:
#  1. builds build/ (Release) and runs every test (CTest) on lavapipe with the Vulkan
#     validation layer on, two at a time: many of them wait on sockets, timers or a browser,
#     and every test passes with a core kept busy (scripts/test-under-load.sh, issue 42),
#     which is what a second test costs it;
#  2. builds the sanitizer build build-sanitize/ (clang, LPV_SANITIZE=ON: AddressSanitizer and
#     UndefinedBehaviorSanitizer; only what its tests need) and runs the tests labelled
#     "sanitize" there: the CLI test, the glTF corpus through lpv-render and lpv-server, and a
#     short run of the glTF loader's fuzzer.
# Arguments are passed to both ctest runs, which select tests within their stage:
#   scripts/test.sh -R corpus    # the corpus tests, in both builds
#   scripts/test.sh -R renderer  # the renderer test (the sanitize stage has none: it runs nothing)
# LPV_TEST_SANITIZE=0 skips stage 2. Both stages run even when the first fails; the exit
# status is non-zero if either failed.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/scripts/build.sh" -DLPV_WERROR=ON

status=0
(cd "$root/build" && ctest --output-on-failure --timeout 600 --parallel 2 "$@") || status=1
# CTest shows a test's output only when it fails: a skipped test's reason ("SKIP ...") is
# printed here, so that no skip goes unexplained.
grep -h '^SKIP ' "$root/build/Testing/Temporary/LastTest.log" 2>/dev/null || true

if [ "${LPV_TEST_SANITIZE:-1}" != 0 ]; then
  echo "== sanitizer build (build-sanitize: clang, AddressSanitizer + UndefinedBehaviorSanitizer)"
  cmake -S "$root" -B "$root/build-sanitize" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DLPV_SANITIZE=ON -DLPV_WERROR=ON >/dev/null
  cmake --build "$root/build-sanitize" --target sanitize-tests --parallel "$(nproc)"
  (cd "$root/build-sanitize" && ctest --output-on-failure --timeout 600 --parallel "$(nproc)" -L sanitize "$@") || status=1
fi
exit "$status"
