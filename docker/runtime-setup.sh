#!/bin/sh
# The runtime image's setup once its packages are in: docker/Dockerfile's runtime stage runs
# it, and so does tests/runtime_image on a root of its own, so that the two cannot drift.
# Usage: runtime-setup.sh (as root, from a folder that also holds healthcheck.sh)
set -eu
here=$(dirname "$0")
# A fixed unprivileged user: the Dockerfile's USER and docker/k8s's runAsUser name 10001.
# Its home holds lpv-render's pipeline cache and Mesa's shader cache.
groupadd --gid 10001 lpv
useradd --uid 10001 --gid lpv --home-dir /home/lpv --create-home --shell /usr/sbin/nologin lpv
# --data-dir (a VOLUME): the scene store and lpv-server's pipeline cache. A new Docker volume
# takes this folder's owner; Kubernetes' fsGroup does the same for its volumes.
install -d -o lpv -g lpv -m 0750 /data
install -m 0755 "$here/healthcheck.sh" /usr/local/bin/lpv-healthcheck
