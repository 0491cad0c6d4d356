# Sourced by the benchmark scripts that measure a local lpv-server (bench-server.sh,
# bench-scene.sh). start_local_server BIN [ARGS...] starts it on a free port with its log in
# $work/server.log (the caller's temporary folder), stops it and removes $work on exit, and
# returns once it answers /readyz. Sets server (its pid) and port.
start_local_server() {
  "$@" --port 0 >"$work/server.log" 2>&1 &
  server=$!
  trap 'kill -TERM $server 2>/dev/null; wait $server 2>/dev/null; rm -rf "$work"' EXIT
  port=""
  for _ in $(seq 600); do
    port=$(head -1 "$work/server.log" | sed -n 's/.*:\([0-9][0-9]*\)$/\1/p')
    [ -n "$port" ] && break
    sleep 0.05
  done
  [ -n "$port" ] || { cat "$work/server.log"; exit 1; }
  until curl -sf "http://127.0.0.1:$port/readyz" >/dev/null; do sleep 0.1; done
}
