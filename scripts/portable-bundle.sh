#!/usr/bin/env bash
# Packs a build (default: build/) into one archive that runs on another x86-64 Linux machine
# without this project's Debian packages, such as a GPU machine with another distribution
# (docs/testing.md, "On another Vulkan device"): the programs and test binaries, the shared
# libraries they load (all but the C and C++ runtimes, which a newer distribution has too),
# the Vulkan loader, the validation layer, the GL vendor-neutral dispatch libraries
# (libglvnd: NVIDIA's Vulkan driver is a GLX vendor library, and without them its
# vkCreateInstance is not found; containers often lack them), HAProxy for the scale-out test
# (where the build found one), the glTF corpus and the tracked source files the tests read.
#
#   scripts/portable-bundle.sh [ARCHIVE [BUILD]]   # defaults: build-portable/lpv-portable.tar.xz, build
#   # on the other machine:
#   mkdir lpv && tar -xJf lpv-portable.tar.xz -C lpv
#   lpv/run.sh ctest --test-dir build -E 'web_(ui|canvas)'  # the suites (no browser there)
#   lpv/run.sh bench/bench-lpv.sh                  # the LPV numbers on its device
#
# run.sh runs its command from the bundle's root with the libraries, the layer and the test
# paths in place.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${2:-$root/build}"
[ -x "$build/lpv-render" ] || { [ -z "${2:-}" ] && "$root/scripts/build.sh"; } ||
  { echo "portable-bundle.sh: $build has no lpv-render: build it first" >&2; exit 2; }
build="$(cd "$build" && pwd)"
archive="${1:-$root/build-portable/lpv-portable.tar.xz}"
mkdir -p "$(dirname "$archive")"
archive="$(cd "$(dirname "$archive")" && pwd)/$(basename "$archive")"
stage="$(mktemp -d "${TMPDIR:-/tmp}/lpv-portable.XXXXXX")"
trap 'rm -rf "$stage"' EXIT
mkdir -p "$stage/lib" "$stage/layers" "$stage/bin"

# The tracked sources as they are in the working tree (the tests' scripts, web/, bench/, api/);
# outside a git checkout (a Docker image), the tree but its builds.
if git -C "$root" rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  git -C "$root" ls-files -z | (cd "$root" && tar --null -T - -cf -) | tar -xf - -C "$stage"
else
  tar -C "$root" --exclude='./build*' --exclude=./node_modules --exclude=./data -cf - . | tar -xf - -C "$stage"
fi

# The build without its objects.
cp -a "$build" "$stage/build"
(cd "$stage/build" && find . \( -name CMakeFiles -o -name Testing -o -name artifacts \) -prune -exec rm -rf {} + &&
  find . -name '*.a' -delete)

# HAProxy, which the scale-out test runs (its path is in the CTest files; run.sh points them here).
haproxy=$(sed -n 's/^LPV_HAPROXY:[A-Z]*=//p' "$build/CMakeCache.txt")
[ -x "$haproxy" ] && cp "$haproxy" "$stage/bin/haproxy" || haproxy=

# Shared libraries: what the binaries and the layer load, but the C and C++ runtimes.
layer=/usr/lib/x86_64-linux-gnu/libVkLayer_khronos_validation.so
layer_json=/usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json
elves=$(find "$stage/build" -type f -perm -u+x -exec sh -c 'head -c4 "$1" | grep -q ELF' _ {} \; -print)
{
  for f in $elves "$layer" ${haproxy:+"$stage/bin/haproxy"}; do ldd "$f" 2>/dev/null | awk '$2 == "=>" && $3 ~ /^\// { print $3 }'; done
  echo "$layer"
  for gl in libGLdispatch.so.0 libGLX.so.0 libGL.so.1 libEGL.so.1 libOpenGL.so.0 libGLESv2.so.2; do
    [ -e "/usr/lib/x86_64-linux-gnu/$gl" ] && echo "/usr/lib/x86_64-linux-gnu/$gl"
  done
} | sort -u | grep -Ev '/(libc|libm|libstdc\+\+|libgcc_s|ld-linux-x86-64|libpthread|libdl|librt)\.so' |
  while read -r lib; do cp -L "$lib" "$stage/lib/$(basename "$lib")"; done
cp "$layer_json" "$stage/layers/"
[ -e "$stage/lib/libGLdispatch.so.0" ] || echo "portable-bundle.sh: no libglvnd here: NVIDIA's driver may not load without it" >&2

corpus=$(sed -n 's/^LPV_GLTF_CORPUS_DIR:[A-Z]*=//p' "$build/CMakeCache.txt")
if [ -n "$corpus" ] && [ -d "$corpus" ]; then
  mkdir -p "$stage/corpus" && cp -r "$corpus" "$stage/corpus/glTF2"
fi

# Where the build was made: run.sh rewrites the CTest files from these to where it is.
printf '%s\n%s\n%s\n%s\n' "$build" "$root" "$corpus" "$haproxy" >"$stage/origin"
cat >"$stage/run.sh" <<'RUN'
#!/usr/bin/env bash
# Runs a command from this bundle's root with its libraries, validation layer and test paths
# (scripts/portable-bundle.sh). Example: ./run.sh ctest --test-dir build -E 'web_(ui|canvas)'
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
export LD_LIBRARY_PATH="$here/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export VK_LAYER_PATH="$here/layers"
# NVIDIA's container toolkit puts the driver's manifest where this loader does not look.
if [ -z "${VK_DRIVER_FILES:-}${VK_ICD_FILENAMES:-}" ]; then
  for f in /usr/local/nvidia/share/vulkan/icd.d/*.json; do
    [ -e "$f" ] && export VK_DRIVER_FILES="$f" VK_ICD_FILENAMES="$f" && break
  done
fi
{ read -r build; read -r source; read -r corpus; read -r haproxy || true; } <"$here/origin"
if [ "$source" != "$here" ]; then
  # Through markers, so that no new path is rewritten again by a later pattern.
  find "$here/build" -name CTestTestfile.cmake -exec sed -i -e "s#$build#@BUILD@#g" -e "s#$source#@SOURCE@#g" \
    ${corpus:+-e "s#$corpus#@CORPUS@#g"} ${haproxy:+-e "s#LPV_HAPROXY=$haproxy#LPV_HAPROXY=@HAPROXY@#g"} \
    -e "s#@BUILD@#$here/build#g" -e "s#@SOURCE@#$here#g" -e "s#@CORPUS@#$here/corpus/glTF2#g" \
    -e "s#@HAPROXY@#$here/bin/haproxy#g" {} +
  printf '%s\n%s\n%s\n%s\n' "$here/build" "$here" "${corpus:+$here/corpus/glTF2}" "${haproxy:+$here/bin/haproxy}" \
    >"$here/origin"
fi
# The server tests read the corpus at the path compiled in: link it there when it is missing.
if [ -n "$corpus" ] && [ ! -e "$corpus" ] && [ -d "$here/corpus/glTF2" ]; then
  { mkdir -p "$(dirname "$corpus")" && ln -s "$here/corpus/glTF2" "$corpus"; } 2>/dev/null ||
    echo "run.sh: $corpus is missing and cannot be made: the tests that upload corpus files will fail" >&2
fi
cd "$here"
exec "$@"
RUN
chmod +x "$stage/run.sh"
tar -C "$stage" -cJf "$archive" .  # XZ_OPT=-0 packs faster, larger
echo "$archive ($(du -h "$archive" | cut -f1))"
