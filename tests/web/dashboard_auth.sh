#!/usr/bin/env bash
# The dashboard under authentication (issue 53 item 4, docs/dashboard.md): with the server's
# auth_secret_file, nothing but the static files is served without a login token; a wrong or
# expired token is refused; a key reads only its own jobs (auth_reads "owner") and cancels only
# them; a cancel without the dashboard's action header, or from another origin, is refused; no
# GET cancels. Real cycloptd and cyclopt-web inside a private network namespace; requests by
# Node's fetch (dashboard_auth.js).
# usage: dashboard_auth.sh CYCLOPTD CYCLOPT CYCLOPT_WEB     exit: 0 pass, 1 fail, 77 skipped
set -euo pipefail
if [ "${CYCLOPT_IN_NETNS:-}" != 1 ]; then
  command -v node > /dev/null || { echo "SKIP: no node (deploy/install-deps.sh --browser installs it)"; exit 77; }
fi
. "$(dirname "$0")/../service/netns.sh"
netns_enter 60 "-n" "$0" "$@"
CYCLOPTD=$1 CYCLOPT=$2 CYCLOPT_WEB=$3
netns_loopback_multicast
export LCM_DEFAULT_URL="udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304"
WORK=$(mktemp -d /tmp/cyclopt-dashboard-auth.XXXXXX)
SERVER='' WEB=''
trap 'kill $WEB $SERVER 2>/dev/null; wait 2>/dev/null; rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*"; tail -n 5 "$WORK/server.log" "$WORK/web.log"; exit 1; }
umask 077
printf 'alice alice-secret-0123456789\nbob bob-secret-0123456789ab\nroot root-secret-0123456789ab admin\n' >"$WORK/keys"
for k in alice bob root; do grep "^$k " "$WORK/keys" >"$WORK/$k.key"; done
printf '{"database": "%s/results.db", "workers": 1, "progress_hz": 5, "auth_secret_file": "%s/keys"}' "$WORK" "$WORK" \
  >"$WORK/cycloptd.json"
"$CYCLOPTD" --config "$WORK/cycloptd.json" >"$WORK/server.log" 2>&1 &
SERVER=$!
for _ in $(seq 100); do "$CYCLOPT" --key-file "$WORK/alice.key" --timeout 0.5 list >/dev/null 2>&1 && break; sleep 0.1; done
echo '{"scene": "walker", "task": "foot_sweep", "name": "alice slow", "foot": "P2-shoes-left-HMT", "point_delay_ms": 200,
  "sweep": {"parameter": "density", "values": "1:1:200"}}' >"$WORK/slow.json"
"$CYCLOPT" --key-file "$WORK/alice.key" submit --spec "$WORK/slow.json" >/dev/null || fail "alice's submission"
PORT=8418
"$CYCLOPT_WEB" --config "$WORK/cycloptd.json" --listen 127.0.0.1:$PORT >"$WORK/web.log" 2>&1 &
WEB=$!
for _ in $(seq 50); do (echo >"/dev/tcp/127.0.0.1/$PORT") 2>/dev/null && break; sleep 0.1; done
token() { "$CYCLOPT_WEB" token --key-file "$WORK/$1.key" --hours "${2:-1}"; }
node "$(dirname "$0")/dashboard_auth.js" "http://127.0.0.1:$PORT" "$(token alice)" "$(token bob)" "$(token root)" \
  "$(token alice 0.0001)" || fail "the dashboard's access checks"
echo "PASS"
