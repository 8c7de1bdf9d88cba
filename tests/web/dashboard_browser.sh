#!/usr/bin/env bash
# The dashboard in a real browser (issue 53 item 5, docs/dashboard.md): Debian's chromium driven by
# puppeteer-core (deploy/install-deps.sh --browser) against cycloptd and cyclopt-web inside a
# private network namespace (unshare -n) whose loopback carries the multicast route. Two small
# jobs, one named <script>alert(1)</script>; dashboard_browser.js asserts what the pages show and
# saves screenshots (and the measured latency) to OUT_DIR.
# usage: dashboard_browser.sh CYCLOPTD CYCLOPT CYCLOPT_WEB OUT_DIR
# exit: 0 pass, 1 fail, 77 skipped (no namespace, no chromium or no puppeteer-core)
set -euo pipefail
PUPPETEER_PREFIX=${CYCLOPT_BROWSER_TEST_PREFIX:-/opt/cyclopt-browser-test}
if [ "${CYCLOPT_IN_NETNS:-}" != 1 ]; then
  CHROMIUM=$(command -v chromium || true)
  [ -n "$CHROMIUM" ] || { echo "SKIP: no chromium (deploy/install-deps.sh --browser installs it)"; exit 77; }
  command -v node > /dev/null || { echo "SKIP: no node (deploy/install-deps.sh --browser installs it)"; exit 77; }
  [ -d "$PUPPETEER_PREFIX/node_modules/puppeteer-core" ] \
    || { echo "SKIP: no puppeteer-core in $PUPPETEER_PREFIX (deploy/install-deps.sh --browser installs it)"; exit 77; }
  export CHROMIUM
fi
. "$(dirname "$0")/../service/netns.sh"
netns_enter 90 "-n" "$0" "$@"
CYCLOPTD=$1 CYCLOPT=$2 CYCLOPT_WEB=$3 OUT_DIR=$4
netns_loopback_multicast
export LCM_DEFAULT_URL="udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304"
WORK=$(mktemp -d /tmp/cyclopt-dashboard.XXXXXX)
SERVER='' WEB=''
trap 'kill $WEB $SERVER 2>/dev/null; wait 2>/dev/null; rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*"; tail -n 5 "$WORK/server.log" "$WORK/web.log"; exit 1; }
printf '{"database": "%s/results.db", "workers": 2, "progress_hz": 5}' "$WORK" >"$WORK/cycloptd.json"
"$CYCLOPTD" --config "$WORK/cycloptd.json" >"$WORK/server.log" 2>&1 &
SERVER=$!
for _ in $(seq 100); do "$CYCLOPT" --timeout 0.5 list >/dev/null 2>&1 && break; sleep 0.1; done
PORT=8417
"$CYCLOPT_WEB" --config "$WORK/cycloptd.json" --listen 127.0.0.1:$PORT >"$WORK/web.log" 2>&1 &
WEB=$!

# 1: slow, so the test watches it run and cancels it; its name must show as text.
echo '{"scene": "walker", "task": "foot_sweep", "name": "<script>alert(1)</script>", "foot": "P2-shoes-left-HMT",
  "point_delay_ms": 250, "sweep": {"parameter": "density", "values": "1:1:200"}}' >"$WORK/slow.json"
# 2: a point-foot sweep over speed: points with an objective land in the job page's chart.
echo '{"scene": "walker", "task": "sweep", "name": "point-foot sweep", "foot": "point",
  "speeds": "0.8:0.02:1.4", "multistart": {"starts": 2, "seed": 3, "scale": 0.02}, "continuation": {"seed_speeds": 1.0}}' >"$WORK/sweep.json"
"$CYCLOPT" submit --spec "$WORK/slow.json" >/dev/null || fail "submitting the slow job"
"$CYCLOPT" submit --spec "$WORK/sweep.json" >/dev/null || fail "submitting the sweep"
for _ in $(seq 50); do (echo >"/dev/tcp/127.0.0.1/$PORT") 2>/dev/null && break; sleep 0.1; done

mkdir -p "$OUT_DIR"
NODE_PATH="$PUPPETEER_PREFIX/node_modules" node "$(dirname "$0")/dashboard_browser.js" \
  "http://127.0.0.1:$PORT" "$CHROMIUM" "$OUT_DIR" || fail "the browser's checks"
echo "PASS"
