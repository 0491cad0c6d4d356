#!/bin/bash
# The runtime image's HEALTHCHECK (docker/Dockerfile; tests/runtime_image runs the same file):
# exit status 0 only when GET /healthz answers 200. The slim image has no curl, and bash's
# /dev/tcp is enough for one request.
# Where: LPV_SERVER_HEALTH_PORT when set (the probes' own listener, whose threads slow clients
# cannot take), else LPV_SERVER_PORT, else 8080; on LPV_SERVER_HOST unless it is a wildcard.
set -u
host=${LPV_SERVER_HOST:-127.0.0.1}
case $host in
  0.0.0.0) host=127.0.0.1 ;;
  ::) host=::1 ;;
esac
port=${LPV_SERVER_HEALTH_PORT:-${LPV_SERVER_PORT:-8080}}
exec 3<>"/dev/tcp/$host/$port" || exit 1
printf 'GET /healthz HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n\r\n' >&3
# A server that accepts but does not answer fails too (Docker's --timeout would also end it).
IFS= read -r -t 5 status <&3 || exit 1
[[ $status == "HTTP/1.1 200 "* ]]
