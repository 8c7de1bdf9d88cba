#!/usr/bin/env bash
# Soak test of cycloptd (issue 57 item 5): for SECONDS, several clients submit small jobs of every
# kind (and cancel and watch some) while a driver kills the server with -9 at random times and
# restarts it, fills the small tmpfs that holds the database until ENOSPC and frees it again, and
# sends malformed traffic (cyclopt-wire-fuzz: mutated and truncated encodings, lying fragments;
# cyclopt-bad-sender: malformed JSON, oversize specs, bad ids). The second half runs with
# authentication: the clients sign with their own keys, a forger signs with a wrong secret and an
# unknown key id. Then the clients stop, the server is restarted once more and the queue drains.
# Every distinct spec also runs once, uninterrupted, on a reference database first.
#
# Invariants checked at the end (any failure: exit 1):
#   - every job in the database is in a final state (done, failed, incomplete, cancelled), and
#     every job id a client was given belongs to the request id that client sent;
#   - no job ended twice (at most one final event), none is cancelled without a cancel request,
#     none of the forger's requests was accepted;
#   - a job's state is its spec's reference state, and its stored rows (keys, parameter, status,
#     objective to 12 digits) equal the reference rows - a subset of them if it was cancelled;
#   - no duplicate point or trajectory; PRAGMA integrity_check ok;
#   - the server's peak RSS (VmHWM of every server process, read before it is stopped) stays
#     within twice the reference server's peak + 64 MiB;
#   - the server never stopped by itself: every server exit is one of the driver's kills.
# Decisions (specs, kill times, episodes, fuzz seeds) come from bash's RANDOM seeded with SEED,
# printed at the start; timing still varies, so a replay repeats the decisions, not the interleaving.
#
# usage: service_soak.sh CYCLOPTD CYCLOPT CYCLOPT_FOOT WIRE_FUZZ BAD_SENDER [SECONDS [SEED]]
#   SECONDS: length of the fault phase (default 120); SEED: default from the clock;
#   CYCLOPT_SOAK_KEEP=1 keeps the databases and logs of a run that passed, too
# exit: 0 pass, 1 fail, 77 skipped (no permission to create the namespaces)
set -euo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
# shellcheck source=netns.sh
source "$HERE/netns.sh"
DURATION=${6:-120}
# The reference (at most 300 s), the fault phase, the drain (at most 300 s), the checks.
netns_enter $((DURATION + 660)) "-n -m" "$0" "$@"

CYCLOPTD=$1 CYCLOPT=$2 CYCLOPT_FOOT=$3 WIRE_FUZZ=$4 BAD_SENDER=$5
SEED=${7:-$(($(date +%s) % 100000))}
CLIENTS=4 MAX_QUEUED=6 DRAIN_SECONDS=300
netns_loopback_multicast
URL="udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304"
export LCM_DEFAULT_URL=$URL
WORK=$(mktemp -d /tmp/cyclopt-soak.XXXXXX)
SERVER="" KEEP=${CYCLOPT_SOAK_KEEP:-0} KILLED=0 STARTS=0 CRASHES=0 EPISODES=0 FUZZ_DATAGRAMS=0 BAD_MESSAGES=0 PEAK_KB=0
cleanup() {
  touch "$WORK/stop"
  [ -n "$SERVER" ] && kill -9 "$SERVER" 2>/dev/null
  jobs -p | xargs -r kill 2>/dev/null
  wait 2>/dev/null
  if [ "$KEEP" = 1 ]; then
    cp "$WORK/disk/results.db" "$WORK/soak.db" 2>/dev/null
    echo "kept for inspection: $WORK (soak.db, reference.db, server.log, client*.log)"
  fi
  umount "$WORK/disk" 2>/dev/null
  [ "$KEEP" = 1 ] || rm -rf "$WORK"
}
trap cleanup EXIT
FAILURES=0
check() {  # check CONDITION-TEXT COMMAND...: counts and prints a failed invariant
  local what=$1
  shift
  if "$@"; then echo "ok: $what"; else echo "FAIL: $what"; FAILURES=$((FAILURES + 1)); fi
}
fail() { echo "FAIL: $*"; tail -30 "$WORK/server.log" 2>/dev/null; KEEP=1; exit 1; }
sql() { sqlite3 -batch -noheader -cmd ".timeout 5000" "$@"; }
echo "seed $SEED (replay: $(basename "$0") ... $DURATION $SEED)"
RANDOM=$SEED

# The specs: the smallest of every kind (tests/service/test_golden_jobs.cpp), point feet at P = 25.
mkdir -p "$WORK/specs" "$WORK/keys" "$WORK/disk"
spec() { printf '%s\n' "$2" >"$WORK/specs/$1.json"; }
spec evaluate_09 '{"scene": "walker", "task": "evaluate", "foot": "point", "points": 25, "solver": {"max_iterations": 600}, "speed": 0.9}'
spec evaluate_10 '{"scene": "walker", "task": "evaluate", "foot": "point", "points": 25, "solver": {"max_iterations": 600}, "speed": 1.0}'
spec evaluate_11 '{"scene": "walker", "task": "evaluate", "foot": "point", "points": 25, "solver": {"max_iterations": 600}, "speed": 1.1}'
spec optimise '{"scene": "walker", "task": "optimise", "foot": "point", "points": 25, "solver": {"max_iterations": 600}, "speed": 1.0}'
spec multistart '{"scene": "walker", "task": "multistart", "foot": "point", "points": 25, "solver": {"max_iterations": 600}, "speed": 1.0,
  "multistart": {"starts": 3, "seed": 2, "scale": 0.05}}'
spec continuation '{"scene": "walker", "task": "continuation", "foot": "point", "points": 25, "solver": {"max_iterations": 600}, "speeds": "1.0:0.1:1.2"}'
spec sweep '{"scene": "walker", "task": "sweep", "foot": "point", "points": 25, "solver": {"max_iterations": 600}, "speeds": "0.9:0.1:1.1",
  "multistart": {"starts": 2, "seed": 3, "scale": 0.02}, "continuation": {"seed_speeds": 1.0}}'
spec sensitivity '{"scene": "walker", "task": "sensitivity", "foot": "point", "points": 25, "solver": {"max_iterations": 600}, "speed": 1.0,
  "parameters": ["m_T"], "steps": 1}'
spec foot_sweep '{"scene": "walker", "task": "foot_sweep", "foot": "P2-shoes-left-HMT", "samples": 5, "sweep": {"parameter": "density", "values": "20:20:60"}}'
# Slowed down (50 ms a point, ~2 s) so that kills and full disks meet it running.
spec foot_sweep_slow '{"scene": "walker", "task": "foot_sweep", "foot": "P2-shoes-left-HMT", "samples": 20, "point_delay_ms": 50, "sweep": {"parameter": "density", "values": "1:1:40"}}'
spec giant_swing '{"scene": "giant_swing", "task": "giant_swing", "motion": "single", "method": "bezier", "options": {"free_coefficients": 4, "steps": 50}}'
spec foot_comparison '{"scene": "walker", "task": "foot_comparison", "solver": {"max_iterations": 600}, "speeds": "1.0:0.1:1.1",
  "points": 40, "feet": ["P1-barefoot-left-HM"], "multistart": {"starts": 2, "seeds": [3, 4], "scale": 0.02}, "continuation": {"seed_speeds": 1.0}}'
spec foot_design '{"scene": "walker", "task": "foot_design", "foot": "P2-shoes-left-HMT", "speeds": "2.2:0.1:2.3", "densities": [10], "design_speed": 2.3, "points": 40, "solver": {"max_iterations": 500}, "multistart": {"starts": 2, "seed": 2, "scale": 0.02}, "sweep_starts": 1, "foot_scale": 0, "continuation": {"seed_speeds": 2.3, "min_trust_region": 0.05, "corrector_max_iterations": 60}}'
"$CYCLOPT_FOOT" synth --preset P1-shoes-left-HMT --trials 2 --noise 0.0005 --out "$WORK/trials" >/dev/null
"$CYCLOPT_FOOT" fit "$WORK/trials/trial1.trc" "$WORK/trials/trial2.trc" --job-spec "$WORK/specs/foot_fit.json" >/dev/null
SPECS=()
for f in "$WORK"/specs/*.json; do SPECS+=("$(basename "$f" .json)"); done

# Keys: one per client, an admin key for the driver; the forger knows client 1's id, not its secret.
for k in $(seq "$CLIENTS"); do printf 'client%d %032x\n' "$k" $((SEED * 7919 + k)) >"$WORK/keys/client$k"; done
printf 'driver %s admin\n' "$(head -c 16 /dev/urandom | od -An -tx1 | tr -d ' \n')" >"$WORK/keys/driver"
cat "$WORK"/keys/client* "$WORK/keys/driver" >"$WORK/keys/server"
printf 'client1 %s\n' "$(head -c 16 /dev/urandom | od -An -tx1 | tr -d ' \n')" >"$WORK/keys/forged"
printf 'intruder %s\n' "$(head -c 16 /dev/urandom | od -An -tx1 | tr -d ' \n')" >"$WORK/keys/unknown"
chmod 600 "$WORK"/keys/*
printf '{"max_queued_jobs": 1000}\n' >"$WORK/open.json"
printf '{"max_queued_jobs": 1000, "auth_secret_file": "%s"}\n' "$WORK/keys/server" >"$WORK/auth.json"

driver_key() { if [ -e "$WORK/auth_on" ]; then echo "$WORK/keys/driver"; else echo ""; fi; }
answers() { CYCLOPT_KEY_FILE=$(driver_key) "$CYCLOPT" --timeout 0.5 list >/dev/null 2>&1; }
start_server() {  # start_server DB CONFIG
  "$CYCLOPTD" --database "$1" --config "$2" --workers 2 >>"$WORK/server.log" 2>&1 &
  SERVER=$!
  STARTS=$((STARTS + 1))
  wait_for 30 answers || fail "the server did not come up"
}
note_peak() {  # the server's peak RSS so far (kB), before it is stopped
  local kb
  kb=$(awk '/VmHWM/ {print $2}' "/proc/$SERVER/status" 2>/dev/null || echo 0)
  [ "${kb:-0}" -gt "$PEAK_KB" ] && PEAK_KB=$kb
  return 0
}
stop_server() {  # stop_server SIGNAL
  note_peak
  kill "-$1" "$SERVER"
  wait "$SERVER" 2>/dev/null || true
  SERVER=""
}
finished() { sql "$1" "SELECT count(*) FROM jobs WHERE state IN ('queued', 'running')" | grep -qx 0; }

echo "== reference: each of the ${#SPECS[@]} specs once, uninterrupted"
REF=$WORK/reference.db
T0=$(date +%s)
start_server "$REF" "$WORK/open.json"
for s in "${SPECS[@]}"; do "$CYCLOPT" submit --spec "$WORK/specs/$s.json" --request-id "$s" >/dev/null || fail "reference: $s not accepted"; done
wait_for 300 finished "$REF" || fail "reference: not finished in 300 s: $(sql "$REF" "SELECT request_id, state FROM jobs")"
stop_server TERM
REF_PEAK_KB=$PEAK_KB PEAK_KB=0
echo "$(($(date +%s) - T0)) s, peak RSS $((REF_PEAK_KB / 1024)) MiB; spec: state, points, run time"
echo "  $(sql "$REF" "SELECT group_concat(printf('%s: %s, %d, %.1f s', request_id, state, (SELECT count(*) FROM solutions s WHERE s.job_id = j.id), run_seconds), '; ') FROM jobs j")"
RSS_BOUND_KB=$((2 * REF_PEAK_KB + 65536))

# A client: submits a random spec under a fresh request id (resent with the same id when no answer
# came, so never twice), then watches it, cancels it or goes on; keeps at most MAX_QUEUED jobs queued.
client() {
  local k=$1 n=0 s rid out rc try id key
  RANDOM=$((SEED + 1000 * k))
  while [ ! -e "$WORK/stop" ]; do
    if [ "$(sql "$DB" "SELECT count(*) FROM jobs WHERE state = 'queued'" 2>/dev/null || echo 0)" -ge "$MAX_QUEUED" ]; then
      sleep 1
      continue
    fi
    s=${SPECS[RANDOM % ${#SPECS[@]}]}
    n=$((n + 1))
    rid="$s.c$k.$n" id=""
    for try in 1 2 3; do
      key=""
      [ -e "$WORK/auth_on" ] && key=$WORK/keys/client$k
      out=$(CYCLOPT_KEY_FILE=$key timeout 30 "$CYCLOPT" --timeout 5 submit --spec "$WORK/specs/$s.json" --request-id "$rid" 2>&1) && rc=0 || rc=$?
      echo "$rid try $try exit $rc: $out" >>"$WORK/client$k.log"
      [ "$rc" -eq 0 ] && id=$(echo "$out" | awk '/^job [0-9]+ / {print $2}') && break
      [ "$rc" -eq 3 ] || break  # refused (signature, full disk): a new request next time
      sleep 1
    done
    [ -n "$id" ] || { sleep 1; continue; }
    echo "$rid $id" >>"$WORK/accepted.txt"
    case $((RANDOM % 10)) in
      0) CYCLOPT_KEY_FILE=$key timeout 30 "$CYCLOPT" --timeout 5 cancel "$id" >>"$WORK/client$k.log" 2>&1 &&
           echo "$id" >>"$WORK/cancelled.txt" || true ;;
      1 | 2 | 3) CYCLOPT_KEY_FILE=$key timeout 40 "$CYCLOPT" --timeout 5 watch "$id" --watch-timeout 30 >/dev/null 2>&1 || true ;;
      *) sleep $((RANDOM % 3)) ;;
    esac
  done
}
# The forger (authenticated half only): every request must be refused.
forger() {
  RANDOM=$((SEED + 99))
  local n=0 out rc
  while [ ! -e "$WORK/stop" ]; do
    sleep 2
    [ -e "$WORK/auth_on" ] || continue
    n=$((n + 1))
    for key in forged unknown; do
      out=$(CYCLOPT_KEY_FILE=$WORK/keys/$key timeout 30 "$CYCLOPT" --timeout 3 submit --spec "$WORK/specs/optimise.json" --request-id "forged.$key.$n" 2>&1) && rc=0 || rc=$?
      echo "forged.$key.$n exit $rc: $out" >>"$WORK/forger.log"
    done
  done
}

echo "== $DURATION s of faults: $CLIENTS clients, kill -9, full disk, malformed traffic; authenticated from half-time"
mount -t tmpfs -o size=256m tmpfs "$WORK/disk"
DB=$WORK/disk/results.db
start_server "$DB" "$WORK/open.json"
CLIENT_PIDS=()
for k in $(seq "$CLIENTS"); do client "$k" & CLIENT_PIDS+=($!); done
forger & CLIENT_PIDS+=($!)
T0=$(date +%s)
CONFIG=$WORK/open.json
alive_or_count_crash() {
  kill -0 "$SERVER" 2>/dev/null && return 0
  local rc=0
  wait "$SERVER" || rc=$?
  CRASHES=$((CRASHES + 1))
  echo "CRASH: cycloptd exited with status $rc without being killed ($(date -u +%T)); log:"
  tail -15 "$WORK/server.log"
  start_server "$DB" "$CONFIG"
}
# The faults come in rounds of a kill, a full disk, hostile datagrams and malformed requests, each
# round in a random order, so that even a short run meets each of them. A round takes ~30 s: a
# single solve cannot resume (a resumed job replays finished solves and runs, sweep_journal.hpp),
# and kills every ~15 s starve the longest, a foot_design's design multistart start (~20-30 s on a
# loaded 2-core machine), which then holds both workers attempt after attempt.
ACTIONS=()
next_action() {
  local i j t
  if [ ${#ACTIONS[@]} -eq 0 ]; then
    ACTIONS=(kill disk fuzz requests)
    for ((i = ${#ACTIONS[@]} - 1; i > 0; i--)); do
      j=$((RANDOM % (i + 1))) t=${ACTIONS[i]}
      ACTIONS[i]=${ACTIONS[j]} ACTIONS[j]=$t
    done
  fi
  ACTION=${ACTIONS[0]}
  ACTIONS=("${ACTIONS[@]:1}")
}
while [ $(($(date +%s) - T0)) -lt "$DURATION" ]; do
  sleep $((2 + RANDOM % 6)).$((RANDOM % 10))
  alive_or_count_crash
  if [ "$CONFIG" = "$WORK/open.json" ] && [ $(($(date +%s) - T0)) -ge $((DURATION / 2)) ]; then
    touch "$WORK/auth_on"
    CONFIG=$WORK/auth.json
    stop_server 9
    KILLED=$((KILLED + 1))
    start_server "$DB" "$CONFIG"
    echo "$(($(date +%s) - T0)) s: restarted with authentication"
    continue
  fi
  next_action
  case $ACTION in
    kill)
      stop_server 9
      KILLED=$((KILLED + 1))
      sleep 0.$((RANDOM % 10))
      start_server "$DB" "$CONFIG"
      ;;
    disk)
      # Fill the file system until ENOSPC, hold, free.
      dd if=/dev/zero of="$WORK/disk/filler" bs=1M status=none 2>/dev/null || true
      EPISODES=$((EPISODES + 1))
      sleep $((2 + RANDOM % 5))
      rm -f "$WORK/disk/filler"
      ;;
    fuzz)
      n=$(timeout 60 "$WIRE_FUZZ" 239.255.76.67 7667 $((200 + RANDOM % 2000)) --seed "$RANDOM") || fail "cyclopt-wire-fuzz failed"
      FUZZ_DATAGRAMS=$((FUZZ_DATAGRAMS + n))
      ;;
    requests)
      # Malformed requests, each answered with a rejection (or, under authentication, the signature one).
      timeout 60 "$BAD_SENDER" --lcm-url "$URL" --count 10 >>"$WORK/bad-sender.log" 2>&1 || true
      BAD_MESSAGES=$((BAD_MESSAGES + 10))
      ;;
  esac
done
touch "$WORK/stop"
wait "${CLIENT_PIDS[@]}" 2>/dev/null || true
alive_or_count_crash
echo "== final restart; the queue drains"
stop_server 9
KILLED=$((KILLED + 1))
start_server "$DB" "$CONFIG"
T1=$(date +%s)
wait_for "$DRAIN_SECONDS" finished "$DB" || echo "the queue did not drain in $DRAIN_SECONDS s"
echo "drained in $(($(date +%s) - T1)) s"
alive_or_count_crash
stop_server TERM

echo "== figures"
cat "$WORK"/accepted.txt >/dev/null 2>&1 || touch "$WORK/accepted.txt"
touch "$WORK/cancelled.txt" "$WORK/forger.log"
SUBMITTED=$(cat "$WORK"/client*.log | grep -c ' try 1 ' || true)
echo "seed $SEED, fault phase $DURATION s, $CLIENTS clients + forger"
echo "requests: $SUBMITTED submitted, $(wc -l <"$WORK/accepted.txt") accepted (given an id), cancel requests $(wc -l <"$WORK/cancelled.txt")"
echo "no answer after 3 tries: $(cat "$WORK"/client*.log | grep -c ' try 3 exit 3' || true); refused, by reason (numbers masked):"
{ grep -h ' exit [124]: ' "$WORK"/client*.log || true; } | sed 's/^.* exit \([124]\): /exit \1: /; s/[0-9][0-9.]*/N/g' | cut -c1-150 | sort | uniq -c | sort -rn | head -5
echo "jobs in the database by state: $(sql "$DB" "SELECT group_concat(state || ' ' || n, ', ') FROM (SELECT state, count(*) n FROM jobs GROUP BY state)")"
echo "jobs by kind: $(sql "$DB" "SELECT group_concat(task || ' ' || n, ', ') FROM (SELECT task, count(*) n FROM jobs GROUP BY task)")"
echo "attempts: $(sql "$DB" "SELECT sum(attempts) FROM jobs") over $(sql "$DB" "SELECT count(*) FROM jobs") jobs, max $(sql "$DB" "SELECT max(attempts) FROM jobs"); points stored $(sql "$DB" "SELECT count(*) FROM solutions")"
echo "faults: kill -9 $KILLED (server starts $STARTS), disk-full episodes $EPISODES, hostile datagrams $FUZZ_DATAGRAMS, malformed requests $BAD_MESSAGES, forged requests $(grep -c ' exit ' "$WORK/forger.log" || true)"
echo "storage-failure log lines: $(grep -c 'could not store\|cannot record' "$WORK/server.log" || true)"
echo "peak RSS: $((PEAK_KB / 1024)) MiB (bound: twice the reference's $((REF_PEAK_KB / 1024)) MiB + 64 = $((RSS_BOUND_KB / 1024)) MiB)"
echo "database: $(du -h "$DB" | cut -f1); the final server process's counters: $(grep -E "cycloptd: datagrams" "$WORK/server.log" | tail -1)"

echo "== invariants"
# The soak jobs with their spec (the request id's first part) and the stored rows, as compared.
ROWS="printf('%.6f', parameter) AS p, status, printf('%.12g', objective) AS o"
sql "$DB" >"$WORK/compare.txt" <<SQL
ATTACH '$REF' AS ref;
CREATE TEMP TABLE accepted (request_id TEXT, job_id INTEGER);
.mode csv
.separator " "
.import $WORK/accepted.txt accepted
.mode list
CREATE TEMP VIEW sj AS SELECT id, state, cancel_requested, substr(request_id, 1, instr(request_id, '.') - 1) AS spec
  FROM main.jobs WHERE instr(request_id, '.') > 0;
CREATE TEMP VIEW sr AS SELECT job_id, curve_index AS c, point_index AS i, $ROWS FROM main.solutions;
CREATE TEMP VIEW rr AS SELECT j.request_id AS spec, curve_index AS c, point_index AS i, $ROWS
  FROM ref.solutions s JOIN ref.jobs j ON j.id = s.job_id;
SELECT 'not_final', count(*) FROM main.jobs WHERE state NOT IN ('done', 'failed', 'incomplete', 'cancelled');
SELECT 'id_mismatch', count(*) FROM accepted a LEFT JOIN main.jobs j ON j.id = a.job_id WHERE j.request_id IS NOT a.request_id;
SELECT 'ended_twice', count(*) FROM (SELECT job_id FROM main.events WHERE kind IN ('done', 'failed', 'incomplete', 'cancelled') GROUP BY job_id HAVING count(*) > 1);
SELECT 'no_final_event', count(*) FROM main.jobs j WHERE NOT EXISTS (SELECT 1 FROM main.events e WHERE e.job_id = j.id AND e.kind IN ('done', 'failed', 'incomplete', 'cancelled'));
SELECT 'cancelled_unasked', count(*) FROM main.jobs WHERE state = 'cancelled' AND cancel_requested = 0;
SELECT 'forged_accepted', count(*) FROM main.jobs WHERE request_id LIKE 'forged.%';
SELECT 'foreign_jobs', count(*) FROM main.jobs WHERE instr(request_id, '.') = 0;
SELECT 'state_differs', count(*) FROM sj JOIN ref.jobs r ON r.request_id = sj.spec WHERE sj.state <> 'cancelled' AND sj.state <> r.state;
SELECT 'rows_extra', count(*) FROM sj JOIN sr ON sr.job_id = sj.id
  WHERE NOT EXISTS (SELECT 1 FROM rr WHERE rr.spec = sj.spec AND rr.c = sr.c AND rr.i = sr.i AND rr.p IS sr.p AND rr.status = sr.status AND rr.o IS sr.o);
SELECT 'rows_missing', count(*) FROM sj JOIN rr ON rr.spec = sj.spec
  WHERE sj.state <> 'cancelled' AND NOT EXISTS (SELECT 1 FROM sr WHERE sr.job_id = sj.id AND sr.c = rr.c AND sr.i = rr.i AND sr.p IS rr.p AND sr.status = rr.status AND sr.o IS rr.o);
SELECT 'duplicate_points', count(*) FROM (SELECT 1 FROM main.solutions GROUP BY job_id, curve_index, point_index HAVING count(*) > 1);
SELECT 'duplicate_trajectories', count(*) FROM (SELECT 1 FROM main.trajectories GROUP BY solution_id HAVING count(*) > 1);
SELECT 'integrity', (SELECT group_concat(integrity_check) FROM pragma_integrity_check);
SQL
figure() { awk -v k="$1" '$1 == k {print $2}' FS='|' "$WORK/compare.txt"; }
zero() { [ "$(figure "$1")" = 0 ]; }
check "every job in a final state ($(figure not_final) not)" zero not_final
check "every id a client was given is its request's ($(figure id_mismatch) not)" zero id_mismatch
check "no job ended twice ($(figure ended_twice) did; $(figure no_final_event) final events not recorded for want of room)" zero ended_twice
check "no job cancelled without a cancel request ($(figure cancelled_unasked))" zero cancelled_unasked
check "no forged request accepted ($(figure forged_accepted); forger's answers: $(grep -c 'signature rejected' "$WORK/forger.log" || true) signature rejected)" zero forged_accepted
check "final states equal the reference's, cancelled jobs aside ($(figure state_differs) differ)" zero state_differs
check "no stored row outside the reference's ($(figure rows_extra))" zero rows_extra
check "no reference row missing from a job that was not cancelled ($(figure rows_missing))" zero rows_missing
check "no duplicate point ($(figure duplicate_points)) or trajectory ($(figure duplicate_trajectories))" \
  bash -c "[ '$(figure duplicate_points)$(figure duplicate_trajectories)' = 00 ]"
check "integrity_check $(figure integrity)" bash -c "[ '$(figure integrity)' = ok ]"
check "peak RSS $((PEAK_KB / 1024)) MiB <= $((RSS_BOUND_KB / 1024)) MiB" test "$PEAK_KB" -le "$RSS_BOUND_KB"
check "the server never stopped by itself ($CRASHES crashes; $KILLED kills by the driver)" test "$CRASHES" -eq 0
[ "$(figure foreign_jobs)" = 0 ] || echo "note: $(figure foreign_jobs) job(s) not submitted by a client (fuzz): $(sql "$DB" "SELECT group_concat(id || ' ' || state, ', ') FROM jobs WHERE instr(request_id, '.') = 0")"
if [ "$FAILURES" -gt 0 ]; then
  sql "$DB" "ATTACH '$REF' AS ref; SELECT j.id, j.request_id, j.state, j.attempts, j.error FROM jobs j WHERE j.state NOT IN ('done', 'failed', 'incomplete', 'cancelled') OR j.state <> coalesce((SELECT r.state FROM ref.jobs r WHERE r.request_id = substr(j.request_id, 1, instr(j.request_id, '.') - 1)), j.state) LIMIT 20"
  echo "FAIL: $FAILURES invariant(s) (seed $SEED)"
  KEEP=1
  exit 1
fi
echo PASS
