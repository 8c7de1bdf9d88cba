#!/usr/bin/env bash
# Issue 53 acceptance 2, the dashboard's costs (docs/dashboard.md): the fleet page with 200 jobs,
# from navigation to its table drawn, and what 10 open job pages cost a running sweep (its run
# time with and without them, alternating, and the CPU seconds of cyclopt-web and of the browser
# meanwhile). The latency from a progress message to the page is measured by the browser test
# (tests/web/dashboard_browser.sh -> bench/results/dashboard_latency.txt). cycloptd (one worker)
# and cyclopt-web run inside a private network namespace; chromium through puppeteer-core
# (deploy/install-deps.sh --browser). With "pinned", cycloptd and cyclopt-web run on CPU 0 and the
# browser on CPU 1 (taskset), as if the pages were open on the researcher's own machine: the sweep's
# run time then shows what the pages cost the server, not the browser's drawing on a shared core.
# With "control" (after "pinned"), each round also runs the sweep beside a plain CPU load on the
# browser's CPU that spends what the round's browser spent (a duty-cycled busy loop, no pages): on
# one host the browser's CPU is not free for the sweep's core (shared caches, clock), and this
# third run says how much of the pages' cost is that rather than the dashboard's.
# usage: dashboard_bench.sh BUILD_DIR [ROUNDS] [pinned [control]]
set -euo pipefail
if [ "${CYCLOPT_IN_NETNS:-}" != 1 ]; then
  exec unshare -n env CYCLOPT_IN_NETNS=1 bash "$0" "$@"
fi
BUILD=$(realpath "$1") ROUNDS=${2:-2} PINNED=${3:-} CONTROL=${4:-}
SERVER_CPU=() BROWSER_CPU=()
if [ "$PINNED" = pinned ]; then SERVER_CPU=(taskset -c 0) BROWSER_CPU=(taskset -c 1); fi
HERE=$(dirname "$(realpath "$0")")
ip link set lo up
ip route add 224.0.0.0/4 dev lo
export LCM_DEFAULT_URL="udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304"
export NODE_PATH=/opt/cyclopt-browser-test/node_modules
CYCLOPT=$BUILD/client/cyclopt
WORK=$(mktemp -d /tmp/cyclopt-dashboard-bench.XXXXXX)
SERVER='' WEB=''
trap 'kill $WEB $SERVER 2>/dev/null; wait 2>/dev/null; rm -rf "$WORK"' EXIT
PORT=8419 URL=http://127.0.0.1:8419

start() {  # a fresh database, cycloptd with one worker, cyclopt-web
  kill $WEB $SERVER 2>/dev/null || true
  wait 2>/dev/null || true
  rm -rf "$WORK/db" && mkdir "$WORK/db"
  printf '{"database": "%s/db/results.db", "workers": 1, "progress_hz": 5, "max_queued_jobs": 1000}' "$WORK" >"$WORK/cycloptd.json"
  "${SERVER_CPU[@]}" "$BUILD/server/cycloptd" --config "$WORK/cycloptd.json" >"$WORK/server.log" 2>&1 &
  SERVER=$!
  for _ in $(seq 100); do "$CYCLOPT" --timeout 0.5 list >/dev/null 2>&1 && break; sleep 0.1; done
  "${SERVER_CPU[@]}" "$BUILD/web/cyclopt-web" --config "$WORK/cycloptd.json" --listen 127.0.0.1:$PORT >"$WORK/web.log" 2>&1 &
  WEB=$!
  for _ in $(seq 50); do (echo >"/dev/tcp/127.0.0.1/$PORT") 2>/dev/null && break; sleep 0.1; done
}
cpu_seconds() { awk -v hz="$(getconf CLK_TCK)" '{ print ($14 + $15) / hz }' "/proc/$1/stat"; }
run_seconds() { "$CYCLOPT" status "$1" | awk '$1 == "run_seconds" { print $2 }'; }

lscpu | grep "Model name"
echo "load average at start: $(cut -d' ' -f1-3 /proc/loadavg)${PINNED:+; cycloptd and cyclopt-web on CPU 0, the browser on CPU 1}"

# 1: the fleet page with 200 jobs (one running, 199 queued behind it).
start
echo '{"scene": "walker", "task": "foot_sweep", "name": "filler", "foot": "P2-shoes-left-HMT", "point_delay_ms": 500,
  "sweep": {"parameter": "density", "values": "1:1:200"}}' >"$WORK/filler.json"
for i in $(seq 200); do "$CYCLOPT" submit --spec "$WORK/filler.json" --request-id "filler-$i" >/dev/null; done
sleep 1.5
"${BROWSER_CPU[@]}" node "$HERE/dashboard_bench.js" fleet "$URL" 200 10

# 2: a point-foot sweep alone and with 10 open pages of it, alternating. The sweep waits in the
# queue behind a gate job until the pages are loaded (the browser's start-up is not the sweep's).
start
echo '{"scene": "walker", "task": "sweep", "name": "measured sweep", "foot": "point",
  "speeds": "0.8:0.005:1.4", "multistart": {"starts": 4, "seed": 3, "scale": 0.02}, "continuation": {"seed_speeds": 1.0}}' >"$WORK/sweep.json"
# The control load: busy for a share `duty` of every 0.1 s.
BURN='import sys, time
duty = float(sys.argv[1])
while True:
    t0 = time.perf_counter()
    while time.perf_counter() - t0 < 0.1 * duty: pass
    time.sleep(0.1 * (1 - duty))'
CONDITIONS="0 10"
if [ "$CONTROL" = control ]; then CONDITIONS="0 10 load"; fi
for round in $(seq "$ROUNDS"); do
  browser_cpu=0 pages_run=1
  for pages in $CONDITIONS; do
    gate=$("$CYCLOPT" submit --spec "$WORK/filler.json" --request-id "gate-$round-$pages" | awk '{ print $2 }')
    id=$("$CYCLOPT" submit --spec "$WORK/sweep.json" --request-id "sweep-$round-$pages" | awk '{ print $2 }')
    : >"$WORK/pages.txt"
    if [ "$pages" = load ]; then
      duty=$(awk -v c="$browser_cpu" -v t="$pages_run" 'BEGIN { d = c / t; printf "%.3f", (d > 0.95 ? 0.95 : d) }')
      "${BROWSER_CPU[@]}" python3 -c "$BURN" "$duty" &
      BROWSER=$!
    elif [ "$pages" -gt 0 ]; then
      "${BROWSER_CPU[@]}" node "$HERE/dashboard_bench.js" pages "$URL" "$id" "$pages" >"$WORK/pages.txt" &
      BROWSER=$!
      for _ in $(seq 600); do grep -q "pages ready" "$WORK/pages.txt" && break; sleep 0.1; done
    fi
    web0=$(cpu_seconds $WEB)
    "$CYCLOPT" cancel "$gate" >/dev/null
    "$CYCLOPT" watch "$id" >/dev/null 2>&1 || true
    web1=$(cpu_seconds $WEB)
    run=$(run_seconds "$id")
    browser=""
    if [ "$pages" = load ]; then
      browser=", the load $(cpu_seconds $BROWSER) CPU s (duty $duty)"
      kill $BROWSER
      wait $BROWSER 2>/dev/null || true
    elif [ "$pages" -gt 0 ]; then
      wait $BROWSER
      browser=", $(tail -1 "$WORK/pages.txt")"
      browser_cpu=$(tail -1 "$WORK/pages.txt" | awk '{ for (i = 1; i < NF; ++i) if ($i == "browser") { print $(i + 1); exit } }')
      pages_run=$run
    fi
    what="$pages job pages open"
    if [ "$pages" = load ]; then what="no page, a CPU load on the browser's CPU"; fi
    echo "round $round, $what: sweep run $run s; cyclopt-web $(awk -v a="$web0" -v b="$web1" 'BEGIN { printf "%.2f", b - a }') CPU s$browser; load $(cut -d' ' -f1 /proc/loadavg)"
  done
done
