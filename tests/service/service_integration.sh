#!/usr/bin/env bash
# Acceptance tests of the service (issue 8) with real processes: cycloptd, cyclopt clients,
# lcm-logger and sqlite3. Everything runs inside a private network namespace this script
# creates (unshare -n), whose loopback carries the multicast route: no LCM datagram can reach
# the host's network. Bounded: the whole run is killed after 170 s.
#
# usage: service_integration.sh CYCLOPTD CYCLOPT BAD_SENDER LOG_CHANNELS docs/results.md
# exit: 0 pass, 1 fail, 77 skipped (no permission to create a network namespace)
set -euo pipefail

HERE=$(cd "$(dirname "$0")" && pwd)
# shellcheck source=netns.sh
source "$HERE/netns.sh"
netns_enter 170 "-n" "$0" "$@"

CYCLOPTD=$1 CYCLOPT=$2 BAD_SENDER=$3 LOG_CHANNELS=$4 README=$5
netns_loopback_multicast

export LCM_DEFAULT_URL="udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304"
URL=$LCM_DEFAULT_URL
test_workspace integration
DB=$WORK/results.db
sql() { sqlite3 -batch -noheader "$DB" "$1"; }
now() { date +%s.%N; }
# Settings come from a config file (flags after it would override it).
printf '{"database": "%s", "lcm_url": "%s", "workers": 2, "max_job_seconds": 120, "progress_hz": 5}' "$DB" "$URL" >"$WORK/cycloptd.json"
start_server() {
  "$CYCLOPTD" --config "$WORK/cycloptd.json" >>"$WORK/server.log" 2>&1 &
  SERVER=$!
  PIDS+=("$SERVER")
  # Ready when it answers a query.
  wait_for 10 "$CYCLOPT" --timeout 0.5 list >/dev/null 2>&1 || fail "server did not come up"
}
sweep_spec() {  # sweep_spec POINTS DELAY_MS
  printf '{"scene": "walker", "task": "foot_sweep", "foot": "P2-shoes-left-HMT", "point_delay_ms": %d, "sweep": {"parameter": "density", "values": "1:1:%d"}}' "$2" "$1"
}

T0=$(now)
lcm-logger -q -f --channel='CYCLOPT_.*' --lcm-url="$URL" "$WORK/cyclopt.lcmlog" &
LOGGER=$!
PIDS+=("$LOGGER")
start_server

echo "== 1. three clients, 200 submissions, 29 of them repeating a request id"
# Each client submits its own ids c<c>-<i>, then the 13 ids shared-0..12 that all three send,
# then resends its first id: 67 + 67 + 66 = 200 submissions, 53 + 53 + 52 + 13 = 171 jobs.
sweep_spec 3 0 >"$WORK/spec3.json"
client() {  # client C UNIQUE_COUNT
  local c=$1 i
  for i in $(seq 1 "$2"); do "$CYCLOPT" submit --spec "$WORK/spec3.json" --request-id "c$c-$i" >/dev/null || return 1; done
  for i in $(seq 0 12); do "$CYCLOPT" submit --spec "$WORK/spec3.json" --request-id "shared-$i" >/dev/null || return 1; done
  "$CYCLOPT" submit --spec "$WORK/spec3.json" --request-id "c$c-1" >/dev/null || return 1
}
T1=$(now)
client 1 53 & C1=$!
client 2 53 & C2=$!
client 3 52 & C3=$!
wait $C1 && wait $C2 && wait $C3 || fail "a client's submission was not acknowledged"
SUBMITTED=$(( 53 + 53 + 52 + 3 * (13 + 1) ))
EXPECTED_JOBS=$(( 53 + 53 + 52 + 13 ))
sql_is() { [ "$(sql "$1")" -eq "$2" ]; }    # sql_is QUERY NUMBER
sql_at_least() { [ "$(sql "$1")" -ge "$2" ]; }
wait_for 60 sql_is "SELECT count(*) FROM jobs WHERE state = 'done'" "$EXPECTED_JOBS" ||
  fail "not all jobs done: $(sql "SELECT state, count(*) FROM jobs GROUP BY state")"
T2=$(now)
JOBS=$(sql "SELECT count(*) FROM jobs")
ROWS=$(sql "SELECT count(*) FROM solutions")
BAD_JOBS=$(sql "SELECT count(*) FROM (SELECT j.id FROM jobs j LEFT JOIN solutions s ON s.job_id = j.id GROUP BY j.id HAVING count(s.id) != 3)")
DUP_ROWS=$(sql "SELECT count(*) FROM (SELECT 1 FROM solutions GROUP BY job_id, curve_index, point_index HAVING count(*) > 1)")
echo "submissions $SUBMITTED -> jobs $JOBS (expected $EXPECTED_JOBS), solution rows $ROWS, jobs without exactly 3 rows $BAD_JOBS, duplicated rows $DUP_ROWS"
[ "$JOBS" -eq "$EXPECTED_JOBS" ] && [ "$ROWS" -eq $(( 3 * EXPECTED_JOBS )) ] && [ "$BAD_JOBS" -eq 0 ] && [ "$DUP_ROWS" -eq 0 ] ||
  fail "wrong job or result counts"
OVERHEAD=$(sql "SELECT printf('%.3f', 1000 * avg(finished_at - started_at - run_seconds)) FROM jobs")
RUN_MS=$(sql "SELECT printf('%.3f', 1000 * avg(run_seconds)) FROM jobs")
THROUGHPUT=$(echo "$T1 $T2 $JOBS" | awk '{printf "%.1f", 1000 * ($2 - $1) / $3}')
SHORT_PUBLISH=$(sql "SELECT printf('%.1f us per job, %.2f %% of run time', 1e6 * avg(publish_seconds), 100 * sum(publish_seconds) / sum(run_seconds)) FROM jobs")
echo "server overhead per job (claim + bookkeeping + commit, outside the job kind): $OVERHEAD ms; job kind run time $RUN_MS ms/job"
echo "end to end, 3 clients (one process launch per submission): $THROUGHPUT ms per job"
echo "progress publication (worker CPU time) on these 3-point jobs, one or two messages each: $SHORT_PUBLISH"

# A graceful restart between phases, so the server logs its submission-handling cost.
kill -TERM "$SERVER"
wait "$SERVER" || fail "server exited with $? on SIGTERM"
echo "submission handling (decode, validate, insert, ack): $(grep -o 'accepted .*handled' "$WORK/server.log" | tail -1)"
start_server

echo "== 2. kill -9 in the middle of a sweep, restart, the job finishes"
sweep_spec 40 50 >"$WORK/spec40.json"
JOB=$("$CYCLOPT" submit --spec "$WORK/spec40.json" --request-id kill-me | awk '{print $2}')
wait_for 20 sql_at_least "SELECT count(*) FROM solutions WHERE job_id = $JOB" 10 || fail "sweep did not start"
kill -9 "$SERVER"
wait "$SERVER" 2>/dev/null || true
BEFORE=$(sql "SELECT count(*) FROM solutions WHERE job_id = $JOB")
STATE=$(sql "SELECT state FROM jobs WHERE id = $JOB")
sql "SELECT point_index, solved_at FROM solutions WHERE job_id = $JOB ORDER BY point_index" >"$WORK/before.txt"
echo "killed with $BEFORE of 40 points stored, job state '$STATE'"
[ "$STATE" = running ] || fail "job should have been running"
start_server
"$CYCLOPT" watch "$JOB" --watch-timeout 30 >"$WORK/watch.txt" 2>"$WORK/watch.err" || fail "watch: $(cat "$WORK/watch.txt" "$WORK/watch.err")"
AFTER=$(sql "SELECT count(*) FROM solutions WHERE job_id = $JOB")
DISTINCT=$(sql "SELECT count(DISTINCT point_index) FROM solutions WHERE job_id = $JOB")
ATTEMPTS=$(sql "SELECT attempts FROM jobs WHERE id = $JOB")
INTEGRITY=$(sql "PRAGMA integrity_check")
KEPT=$(sql "SELECT point_index, solved_at FROM solutions WHERE job_id = $JOB AND point_index < $BEFORE ORDER BY point_index" | diff -q - "$WORK/before.txt" >/dev/null && echo yes || echo no)
PUBLISH=$(sql "SELECT printf('%.6f s of %.3f s = %.4f %%', publish_seconds, run_seconds, 100 * publish_seconds / run_seconds) FROM jobs WHERE id = $JOB")
echo "after restart: $(cat "$WORK/watch.txt")"
echo "rows $AFTER, distinct points $DISTINCT, attempts $ATTEMPTS, pre-kill rows untouched: $KEPT, integrity_check: $INTEGRITY"
echo "progress publication (worker CPU time, 5 Hz) on this 40-point job: $PUBLISH"
[ "$AFTER" -eq 40 ] && [ "$DISTINCT" -eq 40 ] && [ "$ATTEMPTS" -eq 2 ] && [ "$KEPT" = yes ] && [ "$INTEGRITY" = ok ] ||
  fail "kill -9 recovery lost or duplicated rows"
sql "SELECT publish_seconds <= 0.02 * run_seconds FROM jobs WHERE id = $JOB" | grep -qx 1 || fail "progress publication above 2 %"

echo "== 3. malformed and garbage messages"
"$BAD_SENDER" --lcm-url "$URL" --count 1200 || fail "some bad messages were not rejected by name"
kill -0 "$SERVER" || fail "server died"
"$CYCLOPT" submit --foot P2-shoes-left-HMT --sweep k_HM --values 0.02:0.01:0.05 --watch >/dev/null 2>&1 || fail "server unusable after garbage"
echo "server still up and serving"

echo "== 4. cancel a running job; SIGTERM mid-sweep checkpoints it, the next start resumes it"
sweep_spec 100 20 >"$WORK/spec100.json"
CJOB=$("$CYCLOPT" submit --spec "$WORK/spec100.json" | awk '{print $2}')
wait_for 20 sql_at_least "SELECT count(*) FROM solutions WHERE job_id = $CJOB" 2 || fail "job $CJOB did not start"
"$CYCLOPT" cancel "$CJOB" || fail "cancel refused"
wait_for 10 sql_is "SELECT count(*) FROM jobs WHERE id = $CJOB AND state = 'cancelled'" 1 || fail "job $CJOB not cancelled"
"$CYCLOPT" cancel "$CJOB" 2>/dev/null && fail "a second cancel should be refused"
echo "job $CJOB cancelled after $(sql "SELECT count(*) FROM solutions WHERE job_id = $CJOB") of 100 points"
TJOB=$("$CYCLOPT" submit --spec "$WORK/spec40.json" --request-id term-me | awk '{print $2}')
wait_for 20 sql_at_least "SELECT count(*) FROM solutions WHERE job_id = $TJOB" 5 || fail "job $TJOB did not start"
kill -TERM "$SERVER"
wait "$SERVER" || fail "server exited with $? on SIGTERM"
grep -q "stopped cleanly" "$WORK/server.log" || fail "no clean stop"
[ "$(sql "SELECT state FROM jobs WHERE id = $TJOB")" = queued ] || fail "SIGTERM should return job $TJOB to the queue"
CHECKPOINT=$(sql "SELECT count(*) FROM solutions WHERE job_id = $TJOB")
start_server
"$CYCLOPT" watch "$TJOB" --watch-timeout 30 >/dev/null 2>&1 || fail "job $TJOB did not finish after the restart"
[ "$(sql "SELECT count(DISTINCT point_index) || '/' || count(*) FROM solutions WHERE job_id = $TJOB")" = 40/40 ] ||
  fail "job $TJOB has wrong rows after resume"
echo "SIGTERM with $CHECKPOINT of 40 points stored: job requeued, resumed and finished with 40/40 rows"

echo "== 5. the sqlite3 example queries of docs/results.md"
N=0
while IFS= read -r line; do
  cmd=${line#    }
  out=$(eval "${cmd//cyclopt.db/$DB}") || fail "query failed: $cmd"
  [ -n "$out" ] || fail "query printed nothing: $cmd"
  N=$((N + 1))
done < <(grep -E '^    sqlite3 .*cyclopt\.db ' "$README")
[ "$N" -ge 4 ] || fail "found only $N example queries in $README"
echo "$N example queries of $README answered"
"$CYCLOPT" export "$JOB" --out "$WORK/remote.json" 2>/dev/null || fail "remote export"
"$CYCLOPT" export "$JOB" --db "$DB" --out "$WORK/local.json" 2>/dev/null || fail "local export"
cmp -s "$WORK/remote.json" "$WORK/local.json" || fail "remote and local (read-only) exports differ"
grep -q '"trajectories"' "$WORK/local.json" || fail "export lacks trajectories"
echo "export of job $JOB over LCM and from the file opened read-only: identical ($(wc -c <"$WORK/local.json") bytes)"

echo "== 6. lcm-logger recorded our channels"
kill -TERM "$SERVER"
wait "$SERVER" || fail "server exited with $? on SIGTERM"
kill -INT "$LOGGER"; wait "$LOGGER" 2>/dev/null || true
"$LOG_CHANNELS" "$WORK/cyclopt.lcmlog" >"$WORK/channels.txt" || fail "cannot read the LCM log"
for ch in CYCLOPT_SUBMIT CYCLOPT_ACK CYCLOPT_PROGRESS CYCLOPT_DONE CYCLOPT_QUERY CYCLOPT_QUERY_REPLY CYCLOPT_CANCEL; do
  grep -q "^$ch [1-9]" "$WORK/channels.txt" || fail "lcm-logger recorded no $ch"
done
echo "lcm-logger events per channel: $(tr '\n' ' ' <"$WORK/channels.txt")"
echo "PASS in $(echo "$T0 $(now)" | awk '{printf "%.1f", $2 - $1}') s"
