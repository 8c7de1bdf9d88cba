#!/usr/bin/env bash
# A private cyclopt installation to try the quick start in (README): starts cycloptd with the
# database out/sandbox/cyclopt.db (kept between sessions) inside a private network namespace, then
# runs COMMAND there - by default an interactive shell - with `cyclopt`, `cyclopt-foot` and
# `cyclopt-giant-swing` on PATH and LCM_DEFAULT_URL set; the server stops when it ends.
# Nothing leaves the host: LCM's multicast stays on the namespace's loopback. Needs root (unshare)
# and the build (cmake --build build). Server log: out/sandbox/cycloptd.log. Environment: BUILD
# (the build directory, default build), CYCLOPT_SANDBOX (instead of out/sandbox).
#   bash deploy/sandbox.sh                       # a shell; `exit` stops the server
#   bash deploy/sandbox.sh cyclopt list          # one command
#   bash deploy/sandbox.sh bash my_script.sh     # a script of cyclopt commands
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${BUILD:-build}
[[ $BUILD = /* ]] || BUILD=$ROOT/$BUILD
OUT=${CYCLOPT_SANDBOX:-$ROOT/out/sandbox}
if [ "${CYCLOPT_IN_NETNS:-}" != 1 ]; then
  [ -x "$BUILD/server/cycloptd" ] || { echo "sandbox.sh: no $BUILD/server/cycloptd: build first (README)" >&2; exit 4; }
  mkdir -p "$OUT"
  exec unshare -n env CYCLOPT_IN_NETNS=1 bash "$0" "$@"
fi
ip link set lo up
ip route add 224.0.0.0/4 dev lo
export LCM_DEFAULT_URL="udpm://239.255.76.67:7667?ttl=0"
export PATH="$BUILD/client:$BUILD/server:$PATH"
cycloptd --database "$OUT/cyclopt.db" 2>>"$OUT/cycloptd.log" &
SERVER=$!
trap 'kill -TERM $SERVER 2>/dev/null; wait $SERVER 2>/dev/null' EXIT
if [ $# -eq 0 ]; then
  echo "cyclopt sandbox: cycloptd is running (database $OUT/cyclopt.db); 'exit' stops it." >&2
  PS1='(cyclopt) \w\$ ' bash --norc -i
else
  "$@"
fi
