#!/usr/bin/env bash
# Proposed main job of the service (README, "The service"): starts cycloptd with a fresh
# database in out/service/, submits a foot sweep of the default foot (the seed's P2 foot with
# shoes, density 20..60 kg/m^2), watches it and prints the result table.
# LCM traffic stays inside a private network namespace created here (needs root): nothing goes
# on the host's network. Run after the build (cmake --build build).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${BUILD:-build}
OUT=out/service
if [ "${CYCLOPT_IN_NETNS:-}" != 1 ]; then
  mkdir -p "$OUT"
  rm -f "$OUT"/cyclopt.db "$OUT"/cyclopt.db-wal "$OUT"/cyclopt.db-shm
  exec unshare -n env CYCLOPT_IN_NETNS=1 bash "$0" "$@"
fi
ip link set lo up
ip route add 224.0.0.0/4 dev lo
export LCM_DEFAULT_URL="udpm://239.255.76.67:7667?ttl=0"
"$BUILD/server/cycloptd" --database "$OUT/cyclopt.db" 2>"$OUT/cycloptd.log" &
SERVER=$!
trap 'kill -TERM $SERVER 2>/dev/null; wait $SERVER' EXIT
"$BUILD/client/cyclopt" submit --foot P2-shoes-left-HMT --sweep density --values 20:5:60 \
  --point-delay-ms 100 --name "default foot, density sweep" --watch
JOB=$("$BUILD/client/cyclopt" list --json | grep -o '"id": [0-9]*' | tail -1 | grep -o '[0-9]*')
"$BUILD/client/cyclopt" query "$JOB"
echo "database: $OUT/cyclopt.db (read it with: $BUILD/client/cyclopt query $JOB --db $OUT/cyclopt.db)"
