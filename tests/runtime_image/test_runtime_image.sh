#!/usr/bin/env bash
# The runtime image (docker/Dockerfile's last stage) without a Docker daemon: a fresh Debian 12
# root made like debian:12-slim with exactly `scripts/install-deps.sh --list runtime`, set up by
# docker/runtime-setup.sh, lpv-server and lpv-render copied in, then both run the way the image
# runs them: as its user, with its environment, in a root that holds nothing of the source
# tree. Also runs the image's health check command, and prints the root's size against the
# single-stage image it replaced. Needs root (mmdebstrap, chroot, mount namespaces) and
# Debian's mirrors.
#   test_runtime_image.sh SOURCE_DIR LPV_SERVER LPV_RENDER
set -u
source_dir=$1
server_bin=$2
render_bin=$3
. "$source_dir/tests/cli/script_checks.sh"
start=$SECONDS

fail() {
  echo "runtime_image: $*" >&2
  exit 1
}
[ "$(id -u)" -eq 0 ] || fail "needs root: mmdebstrap builds the root and chroot runs in it (CI runs the tests as root)"
command -v mmdebstrap >/dev/null || fail "mmdebstrap not found: scripts/install-deps.sh installs it"
unshare --mount true 2>/dev/null || fail "cannot make a mount namespace: needs CAP_SYS_ADMIN (in a container, a privileged one)"

work=$(mktemp -d "${TMPDIR:-/tmp}/lpv-runtime-image.XXXXXX")
root=$work/root
server_pid=
other_pid=
cleanup() {
  for pid in $server_pid $other_pid; do kill -KILL "$pid" 2>/dev/null; done
  # Every mount lived in a namespace that ended with its command; never cross one all the same.
  rm -rf --one-file-system "$work"
}
trap cleanup EXIT
trap 'exit 1' INT TERM HUP

# debian:12-slim as debuerreotype makes it: minbase, /usr merged as debootstrap does, and dpkg
# told to leave out what "slim" removes (documentation, man pages, translations); its sources,
# and bookworm-backports for the package install-deps.sh takes from there. In a mount namespace
# of its own, so that no mount of mmdebstrap's outlives it.
mirror=http://deb.debian.org/debian
slim=(--dpkgopt='path-exclude=/usr/share/doc/*' --dpkgopt='path-include=/usr/share/doc/*/copyright'
  --dpkgopt='path-exclude=/usr/share/man/*' --dpkgopt='path-exclude=/usr/share/info/*'
  --dpkgopt='path-exclude=/usr/share/groff/*' --dpkgopt='path-exclude=/usr/share/linda/*'
  --dpkgopt='path-exclude=/usr/share/lintian/overrides/*' --dpkgopt='path-exclude=/usr/share/locale/*'
  --dpkgopt='path-include=/usr/share/locale/locale.alias')
packages=$("$source_dir/scripts/install-deps.sh" --list runtime) || fail "scripts/install-deps.sh --list runtime failed"
timeout -k 10 480 unshare --mount --propagation private mmdebstrap --variant=minbase \
  --hook-dir=/usr/share/mmdebstrap/hooks/merged-usr "${slim[@]}" --include="$packages" bookworm "$root" \
  "deb $mirror bookworm main" "deb $mirror bookworm-updates main" "deb $mirror-security bookworm-security main" \
  "deb $mirror bookworm-backports main" >"$work/mmdebstrap.txt" 2>&1 ||
  { tail -n 30 "$work/mmdebstrap.txt"; fail "mmdebstrap could not build the root (are Debian's mirrors reachable?)"; }
mmdebstrap_s=$((SECONDS - start))

# What the Dockerfile's runtime stage does after its packages, with the same files.
image_path=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin  # the debian images' PATH
mkdir "$root/tmp/lpv-setup"
cp "$source_dir/docker/runtime-setup.sh" "$source_dir/docker/healthcheck.sh" "$root/tmp/lpv-setup/"
chroot "$root" env -i PATH="$image_path" /tmp/lpv-setup/runtime-setup.sh || fail "docker/runtime-setup.sh failed in the root"
rm -r "$root/tmp/lpv-setup"
cp "$server_bin" "$render_bin" "$root/usr/local/bin/"

# The runtime stage's instructions, read from the Dockerfile (from its last FROM on): its user,
# environment (one NAME=VALUE per ENV line), volume, entry point and health check command.
stage=$(tac "$source_dir/docker/Dockerfile" | sed '/^FROM /q' | tac)
user=$(sed -n 's/^USER //p' <<<"$stage")
volume=$(sed -n 's/^VOLUME //p' <<<"$stage")
entrypoint=$(sed -n 's/^ENTRYPOINT \["\([^"]*\)"\]$/\1/p' <<<"$stage")
health_command=$(sed -n 's/^HEALTHCHECK .*CMD \["\([^"]*\)"\]$/\1/p' <<<"$stage")
mapfile -t image_env < <(sed -n 's/^ENV //p' <<<"$stage")
uid=${user%%:*}
gid=${user##*:}
check "the image's USER is the user runtime-setup.sh makes" \
  test -n "$user" -a "$user" = "$(chroot "$root" id -u lpv):$(chroot "$root" id -g lpv)"
check "docker/k8s runs as that user" test "$(grep -ho 'run\(AsUser\|AsGroup\): [0-9]*\|fsGroup: [0-9]*' \
  "$source_dir"/docker/k8s/*.yaml | sort -u | tr '\n' ' ')" = "fsGroup: $gid runAsGroup: $gid runAsUser: $uid "
check "the volume is the data directory" bash -c '[ -n "$1" ] && printf "%s\n" "${@:2}" | grep -qx "LPV_SERVER_DATA_DIR=$1"' \
  _ "$volume" "${image_env[@]}"
check "the user owns it" test "$(stat -c %u:%g "$root$volume")" = "$user"
check "mesa-vulkan-drivers is from bookworm-backports (Mesa 25 or later)" \
  dpkg --compare-versions "$(chroot "$root" dpkg-query -W -f='${Version}' mesa-vulkan-drivers)" ge 25
check "no compiler, browser or source tree in the root" \
  bash -c 'for f in "$1"/usr/bin/{cc,c++,gcc,clang,cmake,chromium,node} "$1/src"; do [ ! -e "$f" ] || exit 1; done' _ "$root"

# Docker's environment for the user: PATH, HOME from the user's passwd entry, then the ENV lines.
home=$(chroot "$root" getent passwd "$uid" | cut -d: -f6)
# "${in_root[@]}" [NAME=VALUE...] COMMAND...: runs a command in the root as the image's user,
# with its environment and then the overrides given, as the same process (a signal sent to it
# reaches the command). /proc, /sys (read-only, as Docker has it) and /dev/shm are mounted in a
# mount namespace of the command's own: they end with it however it ends, and the host never
# sees them. /dev is mmdebstrap's, the few nodes Docker gives a container too.
# shellcheck disable=SC2016  # the script of sh -c
in_root=(unshare --mount --propagation private sh -c '
  root=$1 user=$2
  shift 2
  mount -t proc proc "$root/proc" && mount -t sysfs -o ro sysfs "$root/sys" &&
    mount -t tmpfs -o mode=1777 shm "$root/dev/shm" && exec chroot --userspec="$user" "$root" env -i "$@"'
  sh "$root" "$user" PATH="$image_path" HOME="$home" "${image_env[@]}")

# lpv-render as `docker run --entrypoint lpv-render -w /out` runs it, from an empty folder.
install -d -o "$uid" -g "$gid" "$root/out"
echo '{"output": {"width": 96, "height": 64}}' | timeout 120 "${in_root[@]}" env -C /out lpv-render - -q >"$work/render.txt" 2>&1
check "lpv-render renders as the image's user" test $? -eq 0 -a -s "$root/out/cornell-box.png"
check "its PNG signature" test "$(od -An -tx1 -N8 "$root/out/cornell-box.png" | tr -d ' ')" = 89504e470d0a1a0a
check "its PNG is 96x64" test "$(u32be "$root/out/cornell-box.png" 16)x$(u32be "$root/out/cornell-box.png" 20)" = 96x64
check "its pipeline cache is saved in the user's home" test -s "$root$home/.cache/lpv-render/pipeline-cache.bin"

# lpv-server as the image starts it, but on a free loopback port: the port is the first line.
# (timeout passes SIGTERM on to the server and exits with its status.)
timeout 120 "${in_root[@]}" LPV_SERVER_HOST=127.0.0.1 LPV_SERVER_PORT=0 "$entrypoint" >"$work/server.out" 2>"$work/server.err" &
server_pid=$!
port=
for _ in $(seq 300); do
  port=$(sed -n 's|^lpv-server listening on http://127\.0\.0\.1:\([0-9]*\)$|\1|p' "$work/server.out")
  [ -n "$port" ] || ! kill -0 "$server_pid" 2>/dev/null && break
  sleep 0.1
done
[ -n "$port" ] || { cat "$work/server.err"; fail "lpv-server did not start within 30 s"; }
url=http://127.0.0.1:$port
health() { timeout 30 "${in_root[@]}" LPV_SERVER_HOST=127.0.0.1 LPV_SERVER_PORT="$1" "$health_command" >>"$work/health.txt" 2>&1; }
fails() { ! "$@"; }

check "/healthz answers 200" test "$(curl -s -o /dev/null -w '%{http_code}' --max-time 10 "$url/healthz")" = 200
code=$(curl -s --max-time 90 -o "$work/served.png" -w '%{http_code}' -H 'Content-Type: application/json' -d '{}' "$url/v1/render")
check "POST /v1/render answers 200" test "$code" = 200
check "with a PNG" test "$(od -An -tx1 -N8 "$work/served.png" | tr -d ' ')" = 89504e470d0a1a0a
check "GET /v1/device names lavapipe" bash -c 'curl -s --max-time 10 "$1/v1/device" | grep -q llvmpipe' _ "$url"
check "the health check passes while the server runs" health "$port"
# Something else on a port, answering 404 to /healthz: Python's file server (mmdebstrap needs Python).
python3 -u -m http.server --bind 127.0.0.1 --directory "$root/out" 0 >"$work/other.txt" 2>&1 &
other_pid=$!
other_port=
for _ in $(seq 100); do
  other_port=$(sed -n 's/^Serving HTTP on .* port \([0-9]*\) .*/\1/p' "$work/other.txt")
  [ -n "$other_port" ] && break
  sleep 0.1
done
[ -n "$other_port" ] || fail "python3 -m http.server did not start"
check "the health check fails on an answer other than 200" fails health "$other_port"
kill "$other_pid"
other_pid=

kill -TERM "$server_pid"
wait "$server_pid"
check "SIGTERM: the server exits 0" test $? -eq 0
server_pid=
check "the health check fails once the server stopped" fails health "$port"
check "the server saved its pipeline cache in the data directory" test -s "$root$volume/pipeline-cache.bin"
check "no pipeline cache was refused" bash -c '! grep -h "could not save the pipeline cache" "$@"' _ \
  "$work/render.txt" "$work/server.err"

# The sizes. The runtime root by du. The single-stage image it replaced, estimated: debian:12
# (the required and essential packages), every package of `install-deps.sh --list build`, npm,
# and what they depend on, by dpkg's installed sizes as installed here; plus what it held
# beyond packages: the sources (as .dockerignore sends them), tests/web/node_modules and the
# build folder as they are here.
root_mib=$(du -sxm "$root" | cut -f1)
base_and_build=$({ "$source_dir/scripts/install-deps.sh" --list build | sed 's,/.*,,'; echo npm
  dpkg-query -W -f='${Package} ${Priority} ${Essential}\n' | awk '$2 == "required" || $3 == "yes" { print $1 }'; } | sort -u)
# shellcheck disable=SC2086  # one package name a word
packages_mib=$(apt-cache depends --recurse --installed --no-recommends --no-suggests --no-conflicts --no-breaks \
  --no-replaces --no-enhances $base_and_build 2>/dev/null | grep -v '^[ <]' | sort -u |
  xargs dpkg-query -W -f='${Installed-Size}\n' 2>/dev/null | awk '{ kib += $1 } END { printf "%d", kib / 1024 }')
sources_mib=$(du -sm --exclude="$source_dir/.git" --exclude="$source_dir/build*" --exclude=node_modules "$source_dir" | cut -f1)
tree_mib=$(du -scm "$source_dir/tests/web/node_modules" "$(dirname "$server_bin")" 2>/dev/null | tail -n 1 | cut -f1)
tree_mib=$((tree_mib + sources_mib))
echo "runtime root: $root_mib MiB (du); the single-stage image: about $((packages_mib + tree_mib)) MiB" \
  "($packages_mib MiB of packages, $tree_mib MiB of sources, node_modules and build)"
echo "runtime_image: $((SECONDS - start)) s, of which mmdebstrap $mmdebstrap_s s"

finish || {
  for f in render.txt server.out server.err health.txt; do echo "== $f"; cat "$work/$f"; done
  exit 1
}
