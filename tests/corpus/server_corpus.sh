#!/usr/bin/env bash
# Every .gltf and .glb under CORPUS_DIR uploaded to lpv-server (with a temporary --data-dir)
# and rendered at 64x64. Uploads cannot reference external files, so a .gltf with a separate
# .bin or image is uploaded twice: as it is (the server must refuse it), and as
# "NAME+embedded", a copy with the external files that exist next to it turned into data:
# URIs, which goes through the whole loader as the CLI test does. Each upload must either
#   - be accepted: POST /v1/scenes answers 200 or 201 with {"id": ...}, and then
#     POST /v1/render with {"scene": id} answers 200 with a 64x64 PNG, or
#   - be rejected: a 4xx answer (to the upload, or to the render) with a JSON error
#     {"error": {"message": ...}},
# within CORPUS_TIMEOUT seconds per request. A 5xx, no answer, or the server dying fails.
# At the end the server must still be ready, exit 0 on SIGTERM, and its output must hold no
# sanitizer report. tests/corpus/expectations.txt pins the outcome of some files.
#   server_corpus.sh LPV_SERVER CORPUS_DIR
# Environment: CORPUS_TIMEOUT (seconds per request, default 120).
set -u
bin="$(realpath "$1")"
corpus="$(realpath "$2")"
timeout_s=${CORPUS_TIMEOUT:-120}
# shellcheck source=tests/corpus/corpus_lib.sh
. "$(dirname "$0")/corpus_lib.sh"
[ -d "$corpus" ] || { echo "server_corpus: no corpus at $corpus (install assimp-testmodels)"; exit 1; }
work=$(mktemp -d)
server=""
cleanup() {
  if [ -n "$server" ] && kill -0 "$server" 2>/dev/null; then kill -KILL "$server"; fi
  rm -rf "$work"
}
trap cleanup EXIT
cd "$work" || exit 1
mkdir data

"$bin" --port 0 --data-dir "$work/data" >server.log 2>&1 &
server=$!
port=""
for _ in $(seq 1200); do  # up to 60 s: the sanitizer build starts slowly
  port=$(sed -n '1s/^lpv-server listening on http:.*:\([0-9][0-9]*\)$/\1/p' server.log)
  [ -n "$port" ] && break
  kill -0 "$server" 2>/dev/null || break
  sleep 0.05
done
if [ -z "$port" ]; then
  echo "server_corpus: lpv-server did not start"
  cat server.log
  exit 1
fi
base="http://127.0.0.1:$port"
for _ in $(seq 600); do
  [ "$(curl -s -o /dev/null -w '%{http_code}' "$base/readyz")" = 200 ] && break
  sleep 0.1
done
echo "server_corpus: lpv-server on port $port"

# post URL BODY_FILE CONTENT_TYPE: the status in $status, the body in answer.bin.
post() {
  status=$(curl -s -m "$timeout_s" -o answer.bin -w '%{http_code}' -H "Content-Type: $3" \
    --data-binary "@$2" "$1")
}
# Only curl and coreutils (what scripts/install-deps.sh installs): the little JSON read
# here is matched as text. The server writes compact JSON (no spaces).
# A 4xx answer must be {"error": {..., "message": "...", ...}}: prints the message, or fails.
error_message() {
  local message
  message=$(sed -n -E 's/^\{"error":\{.*"message":"(([^"\\]|\\.)+)".*$/\1/p' answer.bin)
  [ -n "$message" ] && printf '%s\n' "$message"
}
# The id of an accepted upload (64 hex digits).
scene_id() { sed -n -E 's/^\{.*"id":"([0-9a-f]{64})".*$/\1/p' answer.bin; }

# embed FILE OUT: writes to OUT a copy of the .gltf FILE whose external files (buffers,
# images) that exist next to it are data: URIs. False when there is none.
embed() {
  local dir text uri mime embedded=0
  dir=$(dirname "$1")
  text=$(<"$1")
  while IFS= read -r uri; do
    [ -f "$dir/$uri" ] || continue
    case "$uri" in
      *.png) mime=image/png ;;
      *.jpg | *.jpeg) mime=image/jpeg ;;
      *) mime=application/octet-stream ;;
    esac
    text=${text//"\"$uri\""/"\"data:$mime;base64,$(base64 -w0 "$dir/$uri")\""}
    embedded=1
  done < <(grep -o '"uri"[[:space:]]*:[[:space:]]*"[^"]*"' "$1" | sed 's/.*"\([^"]*\)"$/\1/' | grep -v '^data:' | sort -u)
  [ "$embedded" -eq 1 ] && printf '%s\n' "$text" >"$2"
}

# url_encode TEXT: TEXT as a URL query value.
url_encode() {
  local i c out=""
  for ((i = 0; i < ${#1}; i++)); do
    c=${1:i:1}
    case "$c" in
      [A-Za-z0-9._~-]) out+=$c ;;
      *) printf -v c '%%%02X' "'$c"; out+=$c ;;
    esac
  done
  printf '%s' "$out"
}

# upload NAME FILE WHERE: uploads FILE, renders it when accepted, and records the outcome
# (WHERE: "upload" or "local", which expectations.txt entries apply).
upload() {
  local name="$1" file="$2" where="$3" stage=upload id size message
  post "$base/v1/scenes?name=$(url_encode "$name")" "$file" application/octet-stream
  if [ "$status" = 200 ] || [ "$status" = 201 ]; then
    id=$(scene_id)
    if [ -z "$id" ]; then
      cp answer.bin answer.txt
      fail "$name" "upload answered $status without an id" answer.txt
      return 0
    fi
    printf '{"scene": "%s", "output": {"width": 64, "height": 64}}\n' "$id" >render.json
    post "$base/v1/render" render.json application/json
    stage=render
  fi
  if ! kill -0 "$server" 2>/dev/null; then
    fail "$name" "the server died during the $stage" server.log
    return 1
  fi
  case "$status" in
    200)
      size=$(png_size answer.bin)
      if [ "$stage" != render ]; then
        fail "$name" "upload answered 200 without an id"
      elif [ "$size" != 64x64 ]; then
        fail "$name" "render answered 200 but not with a 64x64 PNG ($size)"
      elif check_expectation "$where" "${name%+embedded}" render; then
        pass "$name" "rendered $size"
      fi
      ;;
    4??)
      if ! message=$(error_message); then
        cp answer.bin answer.txt
        fail "$name" "$stage answered $status without a JSON error message" answer.txt
      elif check_expectation "$where" "${name%+embedded}" reject; then
        pass "$name" "rejected ($stage $status): $message"
      fi
      ;;
    000) fail "$name" "no answer to the $stage within ${timeout_s}s" ;;
    *)
      cp answer.bin answer.txt
      fail "$name" "$stage answered $status" answer.txt
      ;;
  esac
  return 0
}

while IFS= read -r name; do
  upload "$name" "$corpus/$name" upload || break
  if [[ "$name" == *.gltf ]] && embed "$corpus/$name" embedded.gltf; then
    upload "$name+embedded" embedded.gltf local || break
  fi
done < <(corpus_files)

# The server must still be healthy, stop cleanly, and have nothing to report.
if kill -0 "$server" 2>/dev/null; then
  health=$(curl -s -m 30 -o /dev/null -w '%{http_code}' "$base/readyz")
  [ "$health" = 200 ] || fail "(server)" "GET /readyz answered $health after the corpus"
  kill -TERM "$server"
  for _ in $(seq 600); do kill -0 "$server" 2>/dev/null || break; sleep 0.1; done
  if kill -0 "$server" 2>/dev/null; then
    fail "(server)" "still running 60 s after SIGTERM" server.log
  else
    rc=0
    wait "$server" || rc=$?
    server=""
    [ "$rc" -eq 0 ] || fail "(server)" "exited with status $rc on SIGTERM" server.log
  fi
fi
report=$(sanitizer_report server.log)
[ -z "$report" ] || fail "(server)" "sanitizer report in the server's output" server.log

summary uploads
