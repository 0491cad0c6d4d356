#!/usr/bin/env bash
# The single source of truth for the project's dependencies: Debian 12 packages only.
# Used by scripts/run.sh, scripts/test.sh, .ci/run and docker/Dockerfile.
# Installs only what is missing, so a second run costs one dpkg query.
set -euo pipefail

PACKAGES=(
  # toolchain
  build-essential cmake ninja-build pkg-config
  # Vulkan: loader + headers, lavapipe (CPU driver), validation layers for tests
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers
  # shaders: GLSL -> SPIR-V at build time
  glslang-tools spirv-tools
  # maths, scenes, HTTP, JSON; Embree: ground-truth ray tracing (the reference renderer)
  libglm-dev libtinygltf-dev libcpp-httplib-dev nlohmann-json3-dev libembree-dev
  # image I/O: fast deflate for PNG encoding, stb for decoding in tests, tinyexr for EXR
  libdeflate-dev libstb-dev libtinyexr-dev zlib1g-dev
  # content hashes (SHA-256) of uploaded scenes
  libssl-dev
  # tests and benchmarks; curl for the README's examples and scripts/bench-server.sh
  libgtest-dev libbenchmark-dev curl
  # real and deliberately broken glTF files; clang for the sanitizer build and libFuzzer
  assimp-testmodels clang libclang-rt-dev
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "install-deps: installing ${missing[*]}" >&2
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
