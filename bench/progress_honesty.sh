#!/usr/bin/env bash
# Issue 53 acceptance 3: watch whole jobs and say whether their progress lies. Starts cycloptd
# (one worker) inside a private network namespace, runs the jobs one after another, records every
# progress message (progress_recorder) and prints per job: messages, whether the percentage ever
# decreased, when 100 % first appeared against the job's end, and the ETA's error at 50 %: at the
# first message with percent >= 50, (time + ETA) against the real end, relative to the real rest.
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
CYCLOPT=$BUILD/client/cyclopt
printf '{"database": "%s/results.db", "workers": 1, "max_job_seconds": 3600, "progress_hz": 5}' "$OUT" >"$OUT/cycloptd.json"
"$BUILD/server/cycloptd" --config "$OUT/cycloptd.json" >"$OUT/server.log" 2>&1 &
SERVER=$!
trap 'kill $SERVER 2>/dev/null; wait 2>/dev/null' EXIT
for _ in $(seq 100); do "$CYCLOPT" --timeout 0.5 list >/dev/null 2>&1 && break; sleep 0.1; done

analyse() {  # analyse FILE NAME
  awk -F'\t' -v name="$2" '
    $1 == "end" { end = $2; state = $3; next }
    { n++; t[n] = $1; p[n] = $2; eta[n] = $4; if (n == 1) start = $1 - $5 }
    END {
      dec = 0; worst = 0
      for (i = 2; i <= n; i++) if (p[i] < p[i-1]) { dec++; if (p[i-1] - p[i] > worst) worst = p[i-1] - p[i] }
      first100 = -1; for (i = 1; i <= n; i++) if (p[i] >= 100) { first100 = t[i]; break }
      half = 0; for (i = 1; i <= n; i++) if (p[i] >= 50) { half = i; break }
      printf "%s: %d messages, run %.1f s (%s)\n", name, n, end - start, state
      printf "  percent decreased: %d times (largest step back %.2f points)\n", dec, worst
      if (first100 >= 0) printf "  100%% first at %.2f s after start, %.2f s before the end message\n", first100 - start, end - first100
      else printf "  100%% never shown\n"
      if (half > 0) {
        if (eta[half] == "nan" || eta[half] == "-nan") printf "  at 50%% (%.1f s): ETA unknown\n", t[half] - start
        else {
          rest = end - t[half]
          printf "  at 50%% (%.1f s): ETA %.1f s, real rest %.1f s, error %+.1f s (%+.0f%% of the rest)\n", t[half] - start, eta[half], rest, eta[half] - rest, 100 * (eta[half] - rest) / rest
        }
      }
      m = 0; for (i = 1; i <= n; i++) if (eta[i] != "nan" && eta[i] != "-nan") m++
      printf "  ETA known in %d of %d messages\n", m, n
    }' "$1"
}

run() {  # run NAME SPEC_JSON
  local id
  id=$("$CYCLOPT" submit --spec <(echo "$2") | awk '{print $2}')
  "$BUILD/bench/progress_recorder" "$id" 3600 >"$OUT/$1.tsv" &
  local rec=$!
  sleep 20; COLUMNS=80 "$CYCLOPT" top --once >"$OUT/$1.top.txt" 2>&1 || true
  wait $rec
  analyse "$OUT/$1.tsv" "$1"
}

run point_sweep '{"scene": "walker", "task": "sweep", "foot": "point", "speeds": "0.3:0.1:2.3"}'
run p2_hmt_sweep '{"scene": "walker", "task": "sweep", "foot": "P2-shoes-left-HMT", "speeds": "0.8:0.1:1.6"}'
run two_foot_comparison '{"scene": "walker", "task": "foot_comparison", "speeds": "1.0:0.1:1.3", "points": 50, "feet": ["P1-shoes-left-HM-SG"]}'
echo "phase events of the point sweep: $(sqlite3 "$OUT/results.db" "SELECT count(*) FROM events WHERE job_id = 1 AND kind = 'phase'")"
echo "server log lines: $(wc -l <"$OUT/server.log")"
echo "output: $OUT"
