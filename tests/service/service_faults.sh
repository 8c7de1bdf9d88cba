#!/usr/bin/env bash
# Database faults with the real cycloptd (issue 19, acceptance 4), inside a private network and
# mount namespace this script creates (unshare -n -m), so neither LCM datagrams nor the mounts
# reach the host:
#   1. a read-only directory (a read-only tmpfs: root ignores permission bits) - clear error, exit 4 (file or database error, cli/exit_codes.hpp);
#   2. a corrupt database file (a page overwritten mid-file) - refused at start, file untouched;
#   3. a full disk (a 2 MiB tmpfs) - the failing write re-queues the job (a state change that
#      fails too is retried until there is room), its watcher is told (cyclopt watch exits 2 with
#      the reason), every stored point stays, the job resumes by itself within 10 s of the file
#      system growing (issue 57), integrity_check ok.
#
# usage: service_faults.sh CYCLOPTD CYCLOPT
# exit: 0 pass, 1 fail, 77 skipped (no permission to create the namespaces)
set -euo pipefail

HERE=$(cd "$(dirname "$0")" && pwd)
# shellcheck source=netns.sh
source "$HERE/netns.sh"
netns_enter 110 "-n -m" "$0" "$@"

CYCLOPTD=$1 CYCLOPT=$2
netns_loopback_multicast
export LCM_DEFAULT_URL="udpm://239.255.76.67:7667?ttl=0"
test_workspace faults
on_cleanup() {
  umount "$WORK/ro" "$WORK/small" 2>/dev/null || true
}

# 1. Read-only directory.
mkdir -p "$WORK/ro"
mount -t tmpfs -o ro,size=1m tmpfs "$WORK/ro"
set +e
"$CYCLOPTD" --database "$WORK/ro/results.db" --workers 1 >"$WORK/ro.log" 2>&1
RC=$?
set -e
[ "$RC" -eq 4 ] || fail "read-only directory: exit $RC, expected 4"
grep -q "is not writable" "$WORK/ro.log" || fail "read-only directory: $(cat "$WORK/ro.log")"
echo "read-only directory: exit 4, $(head -1 "$WORK/ro.log")"

# 2. Corrupt database: many rows, then a page in the middle overwritten.
DB=$WORK/corrupt.db
sqlite3 "$DB" "CREATE TABLE filler (x TEXT); WITH RECURSIVE n(i) AS (SELECT 1 UNION ALL SELECT i + 1 FROM n WHERE i < 2000) INSERT INTO filler SELECT printf('%0200d', i) FROM n;"
SIZE=$(stat -c %s "$DB")
dd if=/dev/urandom of="$DB" bs=4096 seek=$(( SIZE / 4096 / 2 )) count=1 conv=notrunc status=none
SUM=$(md5sum <"$DB")
set +e
"$CYCLOPTD" --database "$DB" --workers 1 >"$WORK/corrupt.log" 2>&1
RC=$?
set -e
[ "$RC" -eq 4 ] || fail "corrupt database: exit $RC, expected 4"
grep -q "is damaged (PRAGMA quick_check" "$WORK/corrupt.log" || fail "corrupt database: $(cat "$WORK/corrupt.log")"
[ "$(md5sum <"$DB")" = "$SUM" ] || fail "corrupt database: the server wrote to it"
echo "corrupt database: exit 4, file unchanged, $(head -c 200 "$WORK/corrupt.log")"

# 3. Full disk: a 2 MiB file system; a foot sweep of 3000 points fills it. The job must not stay
#    `running` without a worker (issue 57): its worker retries the state change until the file
#    system has room, then it resumes by itself; measured from the remount that gives room to the
#    first point it stores after it (acceptance: within 10 s).
mkdir -p "$WORK/small"
mount -t tmpfs -o size=2m tmpfs "$WORK/small"
DB=$WORK/small/results.db
"$CYCLOPTD" --database "$DB" --workers 1 >"$WORK/full.log" 2>&1 &
PIDS+=("$!")
for _ in $(seq 100); do "$CYCLOPT" --timeout 0.5 list >/dev/null 2>&1 && break; sleep 0.1; done
SPEC=$WORK/sweep.json
printf '{"scene": "walker", "task": "foot_sweep", "foot": "P2-shoes-left-HMT", "samples": 200, "sweep": {"parameter": "density", "values": "1:0.01:60"}}' >"$SPEC"
# Watching from the submission on: the disk may be full before a separate watch starts.
"$CYCLOPT" submit --spec "$SPEC" --watch --watch-timeout 80 >"$WORK/watch.txt" 2>&1 &
WATCHER=$!
for _ in $(seq 600); do grep -q "could not store a point" "$WORK/full.log" && break; sleep 0.1; done
grep -q "could not store a point" "$WORK/full.log" || fail "full disk: the disk never filled: $(cat "$WORK/full.log")"
sleep 2  # the state change's first tries
JOB=$(sqlite3 "$DB" "SELECT max(id) FROM jobs")
STORED=$(sqlite3 "$DB" "SELECT count(*) FROM solutions WHERE job_id = $JOB")
[ "$STORED" -gt 0 ] || fail "full disk: nothing stored before the disk was full"
RETRYING=no
grep -q "cannot record the job's state" "$WORK/full.log" && RETRYING=yes
echo "full disk: $STORED points stored, state $(sqlite3 "$DB" "SELECT state FROM jobs WHERE id = $JOB"), state change retried: $RETRYING"
mount -o remount,size=256m "$WORK/small"
T0=$(date +%s.%N)
RESUMED=""
for _ in $(seq 300); do
  if [ "$(sqlite3 "$DB" "SELECT count(*) FROM solutions WHERE job_id = $JOB")" -gt "$STORED" ]; then
    RESUMED=$(echo "$T0 $(date +%s.%N)" | awk '{printf "%.2f", $2 - $1}')
    break
  fi
  sleep 0.05
done
[ -n "$RESUMED" ] || fail "full disk: the job did not resume within 15 s of space returning: $(tail -5 "$WORK/full.log")"
echo "full disk: the job resumed $RESUMED s after space returned (acceptance: <= 10 s)"
awk -v t="$RESUMED" 'BEGIN {exit !(t <= 10)}' || fail "full disk: resumed after $RESUMED s, more than 10 s"
wait "$WATCHER" && RC=0 || RC=$?
grep -q "queued: .*could not store a point" "$WORK/watch.txt" || fail "full disk: watcher saw '$(cat "$WORK/watch.txt")'"
[ "$RC" -eq 2 ] || fail "full disk: watch exit $RC, expected 2"
"$CYCLOPT" cancel "$JOB" >/dev/null 2>&1 || true
for _ in $(seq 100); do [ "$(sqlite3 "$DB" "SELECT state FROM jobs WHERE id = $JOB")" = running ] || break; sleep 0.1; done
kill "${PIDS[-1]}"; wait "${PIDS[-1]}" 2>/dev/null || true
[ "$(sqlite3 "$DB" "PRAGMA integrity_check")" = ok ] || fail "full disk: integrity_check"
ROWS=$(sqlite3 "$DB" "SELECT count(*) FROM solutions WHERE job_id = $JOB")
[ "$ROWS" -gt "$STORED" ] || fail "full disk: $ROWS rows stored, $STORED before the disk was full"
STATE=$(sqlite3 "$DB" "SELECT state FROM jobs WHERE id = $JOB")
[ "$STATE" != running ] || fail "full disk: job left running after the server stopped"
echo "full disk: watcher told '$(head -c 240 "$WORK/watch.txt")', exit 2; $ROWS points kept, job $STATE, integrity_check ok"
echo PASS
