#!/usr/bin/env bash
# Issue 53 acceptance 3: watch whole jobs and say whether their progress lies. Starts cycloptd
# (one worker) and cyclopt-web inside a private network namespace, runs the jobs one after another
# and follows each from before it starts to its end in four views at once: every progress message
# (progress_recorder), `cyclopt watch` on a terminal (script), `cyclopt top --interval 1` at 80
# columns and the dashboard's job page (headless chromium, bench/dashboard_bench.js follow). Prints
# per job and view (bench/progress_views.py): percentages shown, whether one ever decreased, when
# 100 % first showed against the job's end message, and the ETA's error at 50 %: at the first
# percentage >= 50, the ETA shown against the real rest of the run.
# usage: progress_honesty.sh BUILD_DIR [OUT_DIR]
set -euo pipefail
if [ "${CYCLOPT_IN_NETNS:-}" != 1 ]; then
  exec unshare -n env CYCLOPT_IN_NETNS=1 bash "$0" "$@"
fi
BUILD=$(realpath "$1") OUT=${2:-$(mktemp -d /tmp/progress-honesty.XXXXXX)}
mkdir -p "$OUT"
ip link set lo up
ip route add 224.0.0.0/4 dev lo
ip route get 239.255.76.67 | grep -q "dev lo" || { echo "multicast not routed to lo"; exit 1; }
export LCM_DEFAULT_URL="udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304"
export NODE_PATH=/opt/cyclopt-browser-test/node_modules
HERE=$(dirname "$(realpath "$0")")
CYCLOPT=$BUILD/client/cyclopt PORT=8419
URL=http://127.0.0.1:$PORT
stamp() { /usr/bin/python3 "$HERE/progress_views.py" stamp; }
printf '{"database": "%s/results.db", "workers": 1, "max_job_seconds": 3600, "progress_hz": 5}' "$OUT" >"$OUT/cycloptd.json"
"$BUILD/server/cycloptd" --config "$OUT/cycloptd.json" >"$OUT/server.log" 2>&1 &
SERVER=$!
trap 'kill $WEB $SERVER 2>/dev/null; wait 2>/dev/null' EXIT
for _ in $(seq 100); do "$CYCLOPT" --timeout 0.5 list >/dev/null 2>&1 && break; sleep 0.1; done
"$BUILD/web/cyclopt-web" --config "$OUT/cycloptd.json" --listen 127.0.0.1:$PORT >"$OUT/web.log" 2>&1 &
WEB=$!
for _ in $(seq 50); do (echo >/dev/tcp/127.0.0.1/$PORT) 2>/dev/null && break; sleep 0.1; done

# A job that holds the one worker until cancelled, so that every view is open before a job starts.
GATE='{"scene": "walker", "task": "foot_sweep", "name": "gate", "foot": "P2-shoes-left-HMT", "point_delay_ms": 500, "sweep": {"parameter": "density", "values": "1:1:200"}}'

run() {  # run NAME SPEC_JSON
  local gate id rec watch top page
  gate=$("$CYCLOPT" submit --spec <(echo "$GATE") | awk '{print $2}')
  id=$("$CYCLOPT" submit --spec <(echo "$2") | awk '{print $2}')
  "$BUILD/bench/progress_recorder" "$id" 3600 >"$OUT/$1.tsv" &
  rec=$!
  script -qfec "$CYCLOPT watch $id" /dev/null </dev/null | stamp >"$OUT/$1.watch.tsv" &
  watch=$!
  COLUMNS=80 "$CYCLOPT" top --interval 1 > >(stamp >"$OUT/$1.top.tsv") 2>&1 &
  top=$!
  node "$HERE/dashboard_bench.js" follow "$URL" "$id" >"$OUT/$1.page.tsv" &
  page=$!
  for _ in $(seq 300); do [ -s "$OUT/$1.page.tsv" ] && break; sleep 0.1; done
  sleep 1
  "$CYCLOPT" cancel "$gate" >/dev/null
  wait $rec $watch $page
  sleep 2
  kill $top
  wait $top || true
  sleep 0.5
  /usr/bin/python3 "$HERE/progress_views.py" analyse "$OUT" "$1" "$id"
}

run point_sweep '{"scene": "walker", "task": "sweep", "foot": "point", "speeds": "0.3:0.1:2.3"}'
run p2_hmt_sweep '{"scene": "walker", "task": "sweep", "foot": "P2-shoes-left-HMT", "speeds": "0.8:0.1:1.6"}'
run two_foot_comparison '{"scene": "walker", "task": "foot_comparison", "speeds": "1.0:0.1:1.3", "points": 50, "feet": ["P1-shoes-left-HM-SG"]}'
echo "server log lines: $(wc -l <"$OUT/server.log")"
echo "output: $OUT"
