#!/usr/bin/env bash
# The single source of truth for the project's dependencies: Debian 12 packages, and the
# npm packages of the browser test and the contract check from their committed lock file
# (tests/web).
#   scripts/install-deps.sh                        # everything to build, test and run
#   scripts/install-deps.sh --runtime              # only what lpv-server and lpv-render need to run
#   scripts/install-deps.sh --list build|runtime   # print a list, one package a line
# Used by scripts/run.sh, scripts/test.sh, .ci/run and docker/Dockerfile (both stages).
# Installs only what is missing, so a second run costs one dpkg query.
set -euo pipefail

# What the two programs load at run time (ldd build/lpv-server build/lpv-render, each library
# to its package with dpkg -S; libc6 and libgcc-s1 are in every Debian root), and the Vulkan
# drivers they render with. Nothing else goes into the runtime image.
RUNTIME_PACKAGES=(
  # the C++ runtime; HTTP (httplib, with brotli and OpenSSL: SHA-256 of uploads)
  libstdc++6 libcpp-httplib0.11 libbrotli1 libssl3
  # image I/O: deflate and zlib for PNG, tinyexr for EXR; Embree and TBB: the reference renderer
  libdeflate0 zlib1g libtinyexr1d libembree3-3 libtbb12
  # Vulkan: the loader, and lavapipe (the CPU driver)
  libvulkan1 mesa-vulkan-drivers
  # libglvnd, for the GPU variant (docs/server.md, "The GPU variant"): NVIDIA's container
  # toolkit mounts the driver's own libraries, not these, yet its Vulkan driver is a GLX (or
  # EGL) vendor library that loads only where libglvnd is (scripts/portable-bundle.sh)
  libglvnd0 libglx0 libegl1
)
# Everything to build and test; the tests run what is built, so the runtime list too.
BUILD_PACKAGES=(
  "${RUNTIME_PACKAGES[@]}"
  # toolchain
  build-essential cmake ninja-build pkg-config
  # Vulkan: loader headers, validation layers for tests
  libvulkan-dev vulkan-validationlayers
  # shaders: GLSL -> SPIR-V at build time
  glslang-tools spirv-tools
  # maths, scenes, HTTP, JSON; Embree: ground-truth ray tracing (the reference renderer)
  libglm-dev libtinygltf-dev libcpp-httplib-dev nlohmann-json3-dev libembree-dev
  # image I/O: fast deflate for PNG encoding, stb for decoding in tests, tinyexr for EXR
  libdeflate-dev libstb-dev libtinyexr-dev zlib1g-dev
  # content hashes (SHA-256) of uploaded scenes
  libssl-dev
  # tests and benchmarks; curl for the README's examples and bench/bench-server.sh
  libgtest-dev libbenchmark-dev curl
  # real and deliberately broken glTF files; clang for the sanitizer build and libFuzzer
  assimp-testmodels clang libclang-rt-dev
  # the web page's browser test (tests/web): Chromium driven by playwright-core on Node.js
  chromium fonts-dejavu-core nodejs
  # the scale-out test: replicas behind HAProxy (tests/server/test_http_scale_out.cpp)
  haproxy
  # the image test (tests/image_runtime): the runtime image's root built without Docker
  mmdebstrap
  # scripts/portable-bundle.sh: xz, and the rest of libglvnd, which it packs for NVIDIA's
  # Vulkan driver
  xz-utils libgl1 libopengl0 libgles2
)

# lavapipe from Mesa 25 or later: Mesa 22.3 (Debian 12's own) runs the same shaders 10% to
# 20% slower, its compute dispatches cost 46 us against 28 (bench/ab-drivers.sh; docs/lpv.md,
# "The driver").
# Debian 12 has it in bookworm-backports, Debian's own archive; Debian 13 in its main suite.
BACKPORTED=mesa-vulkan-drivers
MESA_MIN=25

usage() { echo "usage: install-deps.sh [--runtime | --list build|runtime]" >&2; exit 2; }
case "${1:-}" in
  "") mode=build ;;
  --runtime) mode=runtime ;;
  --list) mode=list ;;
  *) usage ;;
esac
case "$mode:${2:-}" in
  build: | list:build) packages=("${BUILD_PACKAGES[@]}") ;;
  runtime: | list:runtime) packages=("${RUNTIME_PACKAGES[@]}") ;;
  *) usage ;;
esac

# The list as apt names the packages for a fresh Debian 12 root, the images' base (what
# mmdebstrap --include takes): the backported one as NAME/bookworm-backports.
if [ "$mode" = list ]; then
  for p in "${packages[@]}"; do
    if [ "$p" = "$BACKPORTED" ]; then echo "$p/bookworm-backports"; else echo "$p"; fi
  done
  exit 0
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

codename=$(. /etc/os-release && echo "${VERSION_CODENAME:-}")
mesa_version=$(dpkg-query -W -f='${Version}' "$BACKPORTED" 2>/dev/null || true)
backports=()
if [ "$codename" = bookworm ] && ! dpkg --compare-versions "${mesa_version:-0}" ge "$MESA_MIN"; then
  backports=("$BACKPORTED")
  from_main=()
  for p in "${missing[@]}"; do [ "$p" = "$BACKPORTED" ] || from_main+=("$p"); done
  missing=("${from_main[@]}")
fi
# npm: Debian's package, unless the nodejs installed bundles its own (NodeSource's does, and
# conflicts with Debian's npm).
if [ "$mode" = build ]; then command -v npm >/dev/null || missing+=(npm); fi

if [ ${#missing[@]} -gt 0 ] || [ ${#backports[@]} -gt 0 ]; then
  echo "install-deps: installing ${missing[*]} ${backports[*]/%/ (bookworm-backports)}" >&2
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  export DEBIAN_FRONTEND=noninteractive
  if [ ${#backports[@]} -gt 0 ] && ! grep -rqs "bookworm-backports" /etc/apt/sources.list /etc/apt/sources.list.d; then
    printf '%s\n' "Types: deb" "URIs: http://deb.debian.org/debian" "Suites: bookworm-backports" "Components: main" \
      "Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg" | $SUDO tee /etc/apt/sources.list.d/bookworm-backports.sources >/dev/null
  fi
  $SUDO apt-get update -q
  if [ ${#missing[@]} -gt 0 ]; then $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"; fi
  if [ ${#backports[@]} -gt 0 ]; then
    $SUDO apt-get install -y -q --no-install-recommends -t bookworm-backports "${backports[@]}"
  fi
fi

# The browser test's npm packages, exactly as tests/web/package-lock.json pins them, into
# tests/web/node_modules (ignored by git); again only when the lock file changed. (The
# Dockerfile runs this script once before the sources are there: nothing to do then.)
web_test="$(cd "$(dirname "$0")/.." && pwd)/tests/web"
if [ "$mode" = build ] && [ -f "$web_test/package-lock.json" ] &&
  ! cmp -s "$web_test/package-lock.json" "$web_test/node_modules/.installed-lock"; then
  echo "install-deps: npm ci in tests/web" >&2
  (cd "$web_test" && npm ci --no-audit --no-fund)
  cp "$web_test/package-lock.json" "$web_test/node_modules/.installed-lock"
fi
