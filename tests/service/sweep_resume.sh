#!/usr/bin/env bash
# Resume of a walker speed sweep after kill -9 (issue 19 item 5, acceptance 5): the point-foot
# sweep 0.6:0.1:1.4 runs once uninterrupted (database A) and once with cycloptd killed -9 three
# times while it runs (database B, restarted each time). Reports per attempt what was computed
# (multistart solves and continuation runs recorded as checkpoints, solution rows stored), checks
# that the final attempt took over every finished solve and run, and that B's stored rows equal A's
# (keys, speed, status, objective to 12 digits). Runs inside its own network namespace.
#
# Also reports the CPU time (user + sys) of the server processes, whose worker threads compute the
# job: the uninterrupted run's, the killed attempts' together, and the extra the kills cost
# (issue 57: a killed continuation run resumes from its last converged point, journal run_state/<n>).
#
# usage: sweep_resume.sh CYCLOPTD CYCLOPT [STARTS [SPREAD [FOOT [SPEEDS]]]]
#   STARTS: multistart runs per seed speed (default 4); SPREAD: each attempt is killed once it has
#   recorded at least this fraction of the uninterrupted run's checkpoints (default 0: at its first);
#   FOOT (default point) and SPEEDS (default 0.6:0.1:1.4): the sweep's
# exit: 0 pass, 1 fail, 77 skipped (no network namespace)
set -euo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
# shellcheck source=netns.sh
source "$HERE/netns.sh"
netns_enter "${CYCLOPT_RESUME_TIMEOUT:-900}" "-n" "$0" "$@"
CYCLOPTD=$1 CYCLOPT=$2 STARTS=${3:-4} SPREAD=${4:-0} FOOT=${5:-point} SPEEDS=${6:-0.6:0.1:1.4}
netns_loopback_multicast
export LCM_DEFAULT_URL="udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304"
WORK=$(mktemp -d /tmp/cyclopt-resume.XXXXXX)
SERVER=""
cleanup() { [ -n "$SERVER" ] && kill -9 "$SERVER" 2>/dev/null; wait 2>/dev/null; rm -rf "$WORK"; }
trap cleanup EXIT
fail() { echo "FAIL: $*"; tail -20 "$WORK"/server-*.log 2>/dev/null; exit 1; }
start_server() {  # start_server DB
  # shellcheck disable=SC2086  # CYCLOPTD_ARGS: further cycloptd flags, e.g. higher job caps for a long sweep
  "$CYCLOPTD" --database "$1" --workers 1 ${CYCLOPTD_ARGS:-} >>"$WORK/server-$(basename "$1").log" 2>&1 &
  SERVER=$!
  wait_for 10 "$CYCLOPT" --timeout 0.5 list >/dev/null 2>&1 || fail "server did not come up"
}
sql() { sqlite3 -batch -noheader "$1" "$2"; }
cpu_seconds() {  # user + sys CPU seconds of process $1 so far
  awk -v hz="$(getconf CLK_TCK)" '{sub(/^.*\) /, ""); printf "%.2f", ($12 + $13) / hz}' "/proc/$1/stat"
}
cat >"$WORK/sweep.json" <<SPEC
{"scene": "walker", "task": "sweep", "foot": "$FOOT", "speeds": "$SPEEDS", "objective": "f_mech",
 "multistart": {"starts": $STARTS}}
SPEC
# Continuation runs interrupted with a stored run state (run_state/<n> without run/<n>): the next
# attempt continues them from their last converged point.
UNDER_WAY="SELECT count(*) FROM checkpoints c WHERE c.key LIKE 'run_state/%' AND NOT EXISTS
  (SELECT 1 FROM checkpoints d WHERE d.job_id = c.job_id AND d.key = 'run/' || substr(c.key, 11))"
ROWS="SELECT curve_index, point_index, printf('%.6f', parameter), status, printf('%.12g', objective) FROM solutions ORDER BY 1, 2"

echo "== uninterrupted sweep (database A)"
A=$WORK/a.db
T0=$(date +%s.%N)
start_server "$A"
# Exit 5 (incomplete: a required point missing or not converged) is a finished sweep too.
finished() { "$@" && return 0 || { local rc=$?; [ "$rc" -eq 5 ]; }; }
finished "$CYCLOPT" submit --spec "$WORK/sweep.json" --request-id whole --watch >/dev/null 2>"$WORK/watch-a.txt" ||
  fail "uninterrupted sweep failed: $(tail -c 600 "$WORK/watch-a.txt")"
T1=$(date +%s.%N)
CPU_A=$(cpu_seconds "$SERVER")
kill -TERM "$SERVER"; wait "$SERVER" || true; SERVER=""
echo "done in $(echo "$T0 $T1" | awk '{printf "%.1f", $2 - $1}') s, CPU $CPU_A s: $(sql "$A" "SELECT count(*) FROM solutions") rows, $(sql "$A" "SELECT count(*) FROM checkpoints") checkpoints"

echo "== the same sweep, cycloptd killed -9 three times (database B)"
B=$WORK/b.db
start_server "$B"
"$CYCLOPT" submit --spec "$WORK/sweep.json" --request-id killed >/dev/null || fail "submit"
PREV_CP=0 PREV_ROWS=0 CPU_B=0
STEP=$(awk -v n="$(sql "$A" "SELECT count(*) FROM checkpoints")" -v s="$SPREAD" 'BEGIN {k = int(n * s); print (k < 1 ? 1 : k)}')
for k in 1 2 3; do
  # Kill once this attempt has recorded STEP new entries (finished solves or runs) and a bit more.
  wait_for "${CYCLOPT_RESUME_TIMEOUT:-900}" bash -c "[ \$(sqlite3 '$B' 'SELECT count(*) FROM checkpoints') -ge $((PREV_CP + STEP)) ]" || fail "attempt $k recorded too little"
  sleep "0.$((RANDOM % 3 + 1))"
  CPU=$(cpu_seconds "$SERVER")
  kill -9 "$SERVER"; wait "$SERVER" 2>/dev/null || true; SERVER=""
  CPU_B=$(echo "$CPU_B $CPU" | awk '{printf "%.2f", $1 + $2}')
  STATE=$(sql "$B" "SELECT state FROM jobs")
  CP=$(sql "$B" "SELECT count(*) FROM checkpoints") R=$(sql "$B" "SELECT count(*) FROM solutions")
  echo "attempt $k killed ($STATE) after CPU $CPU s: computed and recorded $((CP - PREV_CP)) solves/runs/run states, stored $((R - PREV_ROWS)) rows; runs under way with a stored state: $(sql "$B" "$UNDER_WAY")"
  PREV_CP=$CP PREV_ROWS=$R
  start_server "$B"
  [ "$STATE" = running ] || fail "the job had finished before kill $k: choose a longer sweep (STARTS)"
done
finished "$CYCLOPT" watch 1 --watch-timeout "${CYCLOPT_RESUME_TIMEOUT:-900}" >/dev/null 2>"$WORK/watch-b.txt" || fail "resumed sweep did not finish: $(sql "$B" "SELECT state, error FROM jobs")"
CPU=$(cpu_seconds "$SERVER")
CPU_B=$(echo "$CPU_B $CPU" | awk '{printf "%.2f", $1 + $2}')
kill -TERM "$SERVER"; wait "$SERVER" || true; SERVER=""
echo "final attempt: CPU $CPU s; all attempts CPU $CPU_B s, uninterrupted $CPU_A s: $(echo "$CPU_B $CPU_A" | awk '{printf "%+.1f", 100 * ($1 / $2 - 1)}') % extra"
CP=$(sql "$B" "SELECT count(*) FROM checkpoints") R=$(sql "$B" "SELECT count(*) FROM solutions")
echo "final attempt: computed and recorded $((CP - PREV_CP)) solves/runs, stored $((R - PREV_ROWS)) rows"
WORKDONE=$(sql "$B" "SELECT json_extract(values_json, '$.attempt') FROM solutions WHERE curve_index = 0 LIMIT 1")
echo "final attempt's own count: $WORKDONE"
echo "attempts $(sql "$B" "SELECT attempts FROM jobs"), integrity_check $(sql "$B" "PRAGMA integrity_check")"
[ "$(sql "$B" "SELECT attempts FROM jobs")" -ge 2 ] || fail "the job was never resumed"
RESUMED=$(sql "$B" "SELECT json_extract(values_json, '$.attempt.resumed_solves') + json_extract(values_json, '$.attempt.resumed_runs') FROM solutions WHERE curve_index = 0 LIMIT 1")
[ "$RESUMED" -gt 0 ] || fail "the final attempt took nothing over"
[ "$(sql "$B" "SELECT count(*) FROM checkpoints")" -eq "$(sql "$A" "SELECT count(*) FROM checkpoints")" ] ||
  fail "checkpoints differ: A $(sql "$A" "SELECT count(*) FROM checkpoints"), B $CP"
sql "$A" "$ROWS" >"$WORK/a.txt"
sql "$B" "$ROWS" >"$WORK/b.txt"
diff "$WORK/a.txt" "$WORK/b.txt" >"$WORK/diff.txt" || { head -20 "$WORK/diff.txt"; fail "stored rows differ from the uninterrupted run's"; }
echo "stored rows equal the uninterrupted run's: $(wc -l <"$WORK/a.txt") rows"
echo "PASS"
