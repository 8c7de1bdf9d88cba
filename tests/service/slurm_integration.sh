#!/usr/bin/env bash
# The Slurm executor (issue 18) against a real single-node Slurm cluster (deploy/slurm/local-cluster.sh)
# that this script starts and stops, inside a private network namespace (unshare -n): slurmctld,
# slurmd, munged, cycloptd, the clients and every cyclopt-worker see only this namespace's loopback.
#   1. the same multistart, sweep and foot comparison through the local executor and through Slurm:
#      same points; the comparison's feet and the design's densities and references run as one
#      Slurm job each (work units);
#   2. scancel of a running unit, and kill -9 of a cyclopt-worker: the unit reruns, the job completes,
#      no point lost or duplicated, integrity_check ok;
#   3. kill -9 of cycloptd while a unit runs, restart: re-attached, never submitted twice;
#   2c/3b. the same for the work units of a foot comparison: kill -9 of one foot's worker (that
#      unit alone reruns, resuming from its journal), kill -9 of cycloptd (both re-attached);
#   4. overhead: submission-to-start latency and wall time against the local executor;
#   5. slurmctld stopped for a few seconds while a unit runs, then restarted: the job completes,
#      the unit is not resubmitted (squeue failing is no sign that a unit has ended).
# Figures are printed (bench/results/slurm_executor.txt keeps a run's output).
#
# usage: slurm_integration.sh CYCLOPTD CYCLOPT CYCLOPT_WORKER LOCAL_CLUSTER_SH
# exit: 0 pass, 1 fail, 77 skipped (slurm-wlm/munge not installed, or no network namespace)
set -euo pipefail

if [ "${CYCLOPT_IN_NETNS:-}" != 1 ]; then
  for p in slurmctld slurmd munged sbatch squeue scancel; do
    command -v "$p" >/dev/null 2>&1 || [ -x "/usr/sbin/$p" ] || {
      echo "SKIP: $p not found - the Slurm test needs Debian's slurmctld slurmd slurm-client munge (deploy/install-deps.sh --slurm)"
      exit 77
    }
  done
  unshare -n true 2>/dev/null || { echo "SKIP: cannot create a network namespace (needs root / CAP_SYS_ADMIN)"; exit 77; }
  exec timeout -k 5 520 unshare -n env CYCLOPT_IN_NETNS=1 bash "$0" "$@"
fi

CYCLOPTD=$1 CYCLOPT=$2 WORKER=$3 CLUSTER=$4
ip link set lo up
ip route add 224.0.0.0/4 dev lo
# Slurm resolves names with AI_ADDRCONFIG, which ignores 127.0.0.1: a second loopback address
# (still on lo, still private to this namespace) makes localhost resolvable.
ip addr add 127.0.0.2/8 dev lo
[ "$(ip -o link show | grep -vc ': lo:')" -eq 0 ] || { echo "FAIL: namespace has other interfaces"; exit 1; }

export LCM_DEFAULT_URL="udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304"
WORK=$(mktemp -d /tmp/cyclopt-slurm.XXXXXX)
SERVER=""
cleanup() {
  [ -n "$SERVER" ] && kill "$SERVER" 2>/dev/null || true
  bash "$CLUSTER" stop "$WORK/slurm" >/dev/null 2>&1 || true
  wait 2>/dev/null || true
  rm -rf "$WORK"
}
trap cleanup EXIT
fail() {
  echo "FAIL: $*"
  for f in "$WORK"/server-*.log "$WORK"/slurm/slurmctld.log; do [ -f "$f" ] && { echo "-- $f"; tail -15 "$f"; }; done
  exit 1
}
now() { date +%s.%N; }
minus() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.3f", a - b }'; }
wait_for() {  # wait_for SECONDS COMMAND...
  local deadline=$(( $(date +%s) + $1 )); shift
  until "$@"; do [ "$(date +%s)" -lt "$deadline" ] || return 1; sleep 0.1; done
}

T_CLUSTER=$(now)
bash "$CLUSTER" start "$WORK/slurm" "$(nproc)" || fail "the local Slurm cluster did not start"
export SLURM_CONF=$WORK/slurm/slurm.conf
echo "cluster up in $(minus "$(now)" "$T_CLUSTER") s"
ss -ltn | grep -q '0.0.0.0:16817' && echo "(slurmctld binds all addresses of this namespace: only its loopback exists)"

start_server() {  # start_server NAME EXECUTOR
  local db=$WORK/$1.db
  printf '{"database": "%s", "workers": 2, "max_job_seconds": 200, "progress_hz": 5, "executor": "%s", "slurm": {"spool": "%s", "worker": "%s", "poll_seconds": 0.2, "max_submissions": 4}}' \
    "$db" "$2" "$WORK/spool" "$WORKER" >"$WORK/$1.json"
  "$CYCLOPTD" --config "$WORK/$1.json" >>"$WORK/server-$1.log" 2>&1 &
  SERVER=$!
  wait_for 15 "$CYCLOPT" --timeout 0.5 list >/dev/null 2>&1 || fail "server $1 did not come up"
}
stop_server() { kill "$SERVER"; wait "$SERVER" || true; SERVER=""; }
submit() {  # submit SPEC_JSON -> prints job id
  echo "$1" >"$WORK/spec.json"
  "$CYCLOPT" submit --spec "$WORK/spec.json" | sed -n 's/^job \([0-9]*\).*/\1/p'
}
run_job() {  # run_job SPEC_JSON -> waits; prints "id seconds"
  local t0 id; t0=$(now)
  id=$(submit "$1")
  [ -n "$id" ] || fail "submission not acknowledged"
  "$CYCLOPT" watch "$id" --watch-timeout 200 >/dev/null 2>&1 || fail "job $id did not finish: $("$CYCLOPT" status "$id" 2>&1 | tail -3)"
  echo "$id $(minus "$(now)" "$t0")"
}
points() {  # points DB JOB: curve point parameter objective status, one line each
  sqlite3 -batch -noheader -separator ' ' "$1" \
    "SELECT curve_index, point_index, printf('%.15g', parameter), printf('%.15g', objective), status FROM solutions WHERE job_id = $2 ORDER BY curve_index, point_index"
}
same_points() {  # same_points DB_A JOB_A DB_B JOB_B: equal keys and status, objectives within 1e-10 relative
  paste -d ' ' <(points "$1" "$2") <(points "$3" "$4") | awk '
    { n++; if ($1 != $6 || $2 != $7 || $5 != $10) bad++;
      d = $4 - $9; if (d < 0) d = -d; s = $4 < 0 ? -$4 : $4; if (s < 1) s = 1; if (d > 1e-10 * s) bad++ }
    END { print n " points compared, " bad + 0 " differ"; exit (bad > 0 || n == 0) }'
}
MULTISTART='{"scene": "walker", "task": "multistart", "foot": "point", "speed": 1.0, "objective": "f_mech", "multistart": {"starts": 4, "seed": 3, "scale": 0.05}}'
SWEEP='{"scene": "walker", "task": "sweep", "foot": "point", "speeds": "0.8:0.2:1.2", "objective": "f_mech", "multistart": {"starts": 2, "seed": 1, "scale": 0.05}}'
COMPARISON='{"scene": "walker", "task": "foot_comparison", "speeds": "1.0:0.1:1.1", "points": 50, "feet": ["P1-shoes-left-HM-SG"], "multistart": {"starts": 2, "seed": 3, "scale": 0.02}, "continuation": {"seed_speeds": 1.0}}'
DESIGN="$(cat "$(dirname "$0")/data/small_design.json")"  # with a known design: a design on every host
TINY='{"scene": "walker", "task": "foot_sweep", "foot": "P2-shoes-left-HMT", "sweep": {"parameter": "density", "values": "10:10:30"}}'

echo "== 1. local executor and Slurm store the same points"
start_server local local
read -r L_MS L_MS_T < <(run_job "$MULTISTART")
read -r L_SW L_SW_T < <(run_job "$SWEEP")
read -r L_TINY L_TINY_T < <(run_job "$TINY")
read -r L_CMP L_CMP_T < <(run_job "$COMPARISON")
read -r L_DES L_DES_T < <(run_job "$DESIGN")
stop_server
start_server slurm slurm
read -r S_MS S_MS_T < <(run_job "$MULTISTART")
read -r S_SW S_SW_T < <(run_job "$SWEEP")
read -r S_TINY S_TINY_T < <(run_job "$TINY")
read -r S_CMP S_CMP_T < <(run_job "$COMPARISON")
read -r S_DES S_DES_T < <(run_job "$DESIGN")
echo "multistart: $(same_points "$WORK/local.db" "$L_MS" "$WORK/slurm.db" "$S_MS")" || fail "multistart points differ"
echo "sweep:      $(same_points "$WORK/local.db" "$L_SW" "$WORK/slurm.db" "$S_SW")" || fail "sweep points differ"
same_points "$WORK/local.db" "$L_MS" "$WORK/slurm.db" "$S_MS" >/dev/null || fail "multistart points differ"
same_points "$WORK/local.db" "$L_SW" "$WORK/slurm.db" "$S_SW" >/dev/null || fail "sweep points differ"
echo "comparison: $(same_points "$WORK/local.db" "$L_CMP" "$WORK/slurm.db" "$S_CMP")" || fail "comparison points differ"
same_points "$WORK/local.db" "$L_CMP" "$WORK/slurm.db" "$S_CMP" >/dev/null || fail "comparison points differ"
CMP_UNITS=$(ls -d "$WORK"/spool/cyclopt-"$S_CMP"-*-foot-* 2>/dev/null | wc -l)
CMP_SLURM=0
for d in "$WORK"/spool/cyclopt-"$S_CMP"-*-foot-*; do
  CMP_SLURM=$((CMP_SLURM + $(squeue -h -t all -n "$(basename "$d")" -o %i | sort -u | wc -l)))
done
[ "$CMP_UNITS" = 2 ] && [ "$CMP_SLURM" = 2 ] || fail "comparison: $CMP_UNITS unit spools, $CMP_SLURM Slurm jobs (2 feet: 2 expected)"
echo "comparison: 2 feet -> 2 work units, one Slurm job each"
echo "design:     $(same_points "$WORK/local.db" "$L_DES" "$WORK/slurm.db" "$S_DES")" || fail "design points differ"
same_points "$WORK/local.db" "$L_DES" "$WORK/slurm.db" "$S_DES" >/dev/null || fail "design points differ"
DES_UNITS=$(ls -d "$WORK"/spool/cyclopt-"$S_DES"-*-* 2>/dev/null | sed 's/.*-[0-9a-f]\{8\}-//' | sort | tr '\n' ' ')
[ "$DES_UNITS" = "density-0 point-feet start-foot " ] || fail "design: units '$DES_UNITS' (density-0 point-feet start-foot expected)"
echo "design: 1 density and 2 references -> units $DES_UNITS"

echo "== 4. overhead"
printf 'wall s      local    slurm\nmultistart  %6.2f  %6.2f\nsweep       %6.2f  %6.2f\n3-point job %6.2f  %6.2f\ncomparison  %6.2f  %6.2f  (2 feet: 2 units in parallel on Slurm, one after another locally)\ndesign      %6.2f  %6.2f  (3 units: 2 references, 1 density)\n' \
  "$L_MS_T" "$S_MS_T" "$L_SW_T" "$S_SW_T" "$L_TINY_T" "$S_TINY_T" "$L_CMP_T" "$S_CMP_T" "$L_DES_T" "$S_DES_T"
# Submission-to-start latency per unit: unit.json's submitted_at (just before sbatch) to the
# worker's started.json.
for d in $(ls -d "$WORK"/spool/cyclopt-"$S_MS"-* "$WORK"/spool/cyclopt-"$S_SW"-* "$WORK"/spool/cyclopt-"$S_TINY"-* "$WORK"/spool/cyclopt-"$S_CMP"-* "$WORK"/spool/cyclopt-"$S_DES"-*); do
  python3 -c 'import json,sys; d=sys.argv[1]; s=json.load(open(d+"/unit.json"))["submitted_at"]; t=json.load(open(d+"/started.json"))["started_at"]; print("unit %s: sbatch -> cyclopt-worker running %.3f s" % (d.rsplit("/",1)[1], t - s))' "$d"
done

unit_of() { ls -d "$WORK"/spool/cyclopt-"$1"-* 2>/dev/null | head -1; }
slurm_ids() { squeue -h -t all -n "$(basename "$(unit_of "$1")")" -o %i | sort -u; }
stored() { sqlite3 -batch -noheader "$WORK/slurm.db" "SELECT count(*) FROM solutions WHERE job_id = $1"; }
SLOW='{"scene": "walker", "task": "foot_sweep", "foot": "P2-shoes-left-HMT", "point_delay_ms": 250, "sweep": {"parameter": "density", "values": "1:1:24"}}'
check_slow_job() {  # check_slow_job JOB WHAT
  "$CYCLOPT" watch "$1" --watch-timeout 120 >/dev/null 2>&1 || fail "$2: job $1 did not complete"
  local n dup
  n=$(stored "$1")
  dup=$(sqlite3 -batch -noheader "$WORK/slurm.db" "SELECT count(*) - count(DISTINCT point_index) FROM solutions WHERE job_id = $1")
  [ "$n" = 24 ] && [ "$dup" = 0 ] || fail "$2: $n points stored (24 expected), $dup duplicated"
  echo "$2: job $1 done, 24/24 points, none duplicated, Slurm jobs: $(slurm_ids "$1" | wc -l)"
}

echo "== 2a. scancel of a running unit"
J=$(submit "$SLOW")
wait_for 60 bash -c "[ \$(sqlite3 -batch -noheader $WORK/slurm.db 'SELECT count(*) FROM solutions WHERE job_id = $J') -ge 4 ]" || fail "no progress"
scancel "$(slurm_ids "$J" | head -1)"
echo "scancel after $(stored "$J") points"
check_slow_job "$J" "scancel"
[ "$(slurm_ids "$J" | wc -l)" -ge 2 ] || fail "scancel: the unit was not resubmitted"

echo "== 2b. kill -9 of a cyclopt-worker"
J=$(submit "$SLOW")
wait_for 60 bash -c "[ \$(sqlite3 -batch -noheader $WORK/slurm.db 'SELECT count(*) FROM solutions WHERE job_id = $J') -ge 4 ]" || fail "no progress"
pkill -9 -f "cyclopt-worker --unit $(unit_of "$J")" || fail "no cyclopt-worker process to kill"
echo "kill -9 of the worker after $(stored "$J") points"
check_slow_job "$J" "kill -9 worker"

echo "== 3. kill -9 of cycloptd while its unit runs in Slurm, restart"
J=$(submit "$SLOW")
wait_for 60 bash -c "[ \$(sqlite3 -batch -noheader $WORK/slurm.db 'SELECT count(*) FROM solutions WHERE job_id = $J') -ge 4 ]" || fail "no progress"
kill -9 "$SERVER"; wait "$SERVER" 2>/dev/null || true; SERVER=""
echo "cycloptd killed after $(stored "$J") points; unit state $(squeue -h -t all -j "$(slurm_ids "$J" | head -1)" -o %T)"
sleep 1
start_server slurm slurm
check_slow_job "$J" "kill -9 cycloptd"
[ "$(slurm_ids "$J" | wc -l)" = 1 ] || fail "kill -9 cycloptd: the unit was submitted $(slurm_ids "$J" | wc -l) times"
grep -q "re-attached" "$WORK/server-slurm.log" || fail "kill -9 cycloptd: no re-attach logged"

# A comparison whose two feet (units) sweep 4 speeds each: long enough to be hit while running.
LONG_CMP='{"scene": "walker", "task": "foot_comparison", "speeds": "0.8:0.1:1.1", "points": 50, "feet": ["P1-shoes-left-HM-SG"], "multistart": {"starts": 2, "seed": 3, "scale": 0.02}, "continuation": {"seed_speeds": 0.8}}'
unit_dir() { ls -d "$WORK"/spool/cyclopt-"$1"-*-"$2" 2>/dev/null | head -1; }
unit_slurm_jobs() { squeue -h -t all -n "$(basename "$(unit_dir "$1" "$2")")" -o %i | sort -u | wc -l; }
running_unit() { [ -n "$(unit_dir "$1" "$2")" ] && [ -f "$(unit_dir "$1" "$2")/started.json" ]; }
check_comparison() {  # check_comparison JOB WHAT: done, 4*2 + 4 + 2 points, none duplicated
  "$CYCLOPT" watch "$1" --watch-timeout 200 >/dev/null 2>&1 || fail "$2: job $1 did not complete: $("$CYCLOPT" status "$1" 2>&1 | tail -2)"
  local n dup
  n=$(stored "$1")
  dup=$(sqlite3 -batch -noheader "$WORK/slurm.db" "SELECT count(*) - count(DISTINCT curve_index || '/' || point_index) FROM solutions WHERE job_id = $1")
  [ "$n" = 14 ] && [ "$dup" = 0 ] || fail "$2: $n points stored (14 expected), $dup duplicated"
}

echo "== 2c. kill -9 of the cyclopt-worker of one foot of a comparison"
J=$(submit "$LONG_CMP")
wait_for 60 running_unit "$J" foot-1 || fail "unit foot-1 did not start"
wait_for 60 bash -c "ls $(unit_dir "$J" foot-1)/events | grep -q ." || fail "unit foot-1 wrote nothing"
pkill -9 -f "cyclopt-worker --unit $(unit_dir "$J" foot-1)" || fail "no cyclopt-worker of foot-1 to kill"
check_comparison "$J" "kill -9 of a unit's worker"
[ "$(unit_slurm_jobs "$J" foot-1)" = 2 ] && [ "$(unit_slurm_jobs "$J" foot-0)" = 1 ] ||
  fail "kill -9 of a unit's worker: Slurm jobs foot-0 $(unit_slurm_jobs "$J" foot-0), foot-1 $(unit_slurm_jobs "$J" foot-1) (1 and 2 expected)"
echo "kill -9 of foot-1's worker: job $J done, 14/14 points, none duplicated, Slurm jobs foot-0 1, foot-1 2 (rerun)"

echo "== 3b. kill -9 of cycloptd while a comparison's units run in Slurm, restart"
J=$(submit "$LONG_CMP")
wait_for 60 running_unit "$J" foot-0 || fail "unit foot-0 did not start"
wait_for 60 running_unit "$J" foot-1 || fail "unit foot-1 did not start"
kill -9 "$SERVER"; wait "$SERVER" 2>/dev/null || true; SERVER=""
sleep 1
start_server slurm slurm
check_comparison "$J" "kill -9 cycloptd (units)"
[ "$(unit_slurm_jobs "$J" foot-0)" = 1 ] && [ "$(unit_slurm_jobs "$J" foot-1)" = 1 ] ||
  fail "kill -9 cycloptd (units): a unit was submitted twice (foot-0 $(unit_slurm_jobs "$J" foot-0), foot-1 $(unit_slurm_jobs "$J" foot-1))"
echo "kill -9 cycloptd with 2 units running: job $J done, 14/14 points, none duplicated, each unit 1 Slurm job"
echo "== 5. the Slurm controller down while a unit runs"
# squeue waits ~10 s (MessageTimeout) for an unreachable controller before it fails, and a poll
# of one unit asks twice (slurm_states), so the outage lasts 30 s; 24 points at 3 s outlive it.
J=$(submit "${SLOW/\"point_delay_ms\": 250/\"point_delay_ms\": 3000}")
wait_for 60 bash -c "[ \$(sqlite3 -batch -noheader $WORK/slurm.db 'SELECT count(*) FROM solutions WHERE job_id = $J') -ge 4 ]" || fail "no progress"
CTLD=$(cat "$WORK/slurm/slurmctld.pid")
kill "$CTLD"
wait_for 30 bash -c "! kill -0 $CTLD 2>/dev/null" || fail "slurmctld did not stop"
echo "slurmctld stopped after $(stored "$J") points"
sleep 30
/usr/sbin/slurmctld -f "$WORK/slurm/slurm.conf" || fail "slurmctld did not restart"
echo "slurmctld restarted with its saved state after $(stored "$J") points"
check_slow_job "$J" "slurmctld outage"
[ "$(slurm_ids "$J" | wc -l)" = 1 ] || fail "slurmctld outage: the unit was submitted $(slurm_ids "$J" | wc -l) times"
grep -q "cannot reach the Slurm controller" "$WORK/server-slurm.log" || fail "slurmctld outage: not logged"
grep -q "squeue answers again" "$WORK/server-slurm.log" || fail "slurmctld outage: its end not logged"

[ "$(sqlite3 "$WORK/slurm.db" 'PRAGMA integrity_check')" = ok ] || fail "integrity_check"
echo "integrity_check ok"
stop_server
echo "PASS"
