#!/usr/bin/env bash
# Database faults with the real cycloptd (issue 19, acceptance 4), inside a private network and
# mount namespace this script creates (unshare -n -m), so neither LCM datagrams nor the mounts
# reach the host:
#   1. a read-only directory (a read-only tmpfs: root ignores permission bits) - clear error, exit 4 (file or database error, cli/exit_codes.hpp);
#   2. a corrupt database file (a page overwritten mid-file) - refused at start, file untouched;
#   3. a full disk (a 2 MiB tmpfs) - the failing write re-queues the job, its watcher is told
#      (cyclopt watch exits 2 with the reason), every stored point stays, integrity_check ok.
#
# usage: service_faults.sh CYCLOPTD CYCLOPT
# exit: 0 pass, 1 fail, 77 skipped (no permission to create the namespaces)
set -euo pipefail

if [ "${CYCLOPT_IN_NETNS:-}" != 1 ]; then
  if ! unshare -n -m true 2>/dev/null; then
    echo "SKIP: cannot create network and mount namespaces (needs root / CAP_SYS_ADMIN)"
    exit 77
  fi
  exec timeout -k 5 100 unshare -n -m --propagation private env CYCLOPT_IN_NETNS=1 bash "$0" "$@"
fi

CYCLOPTD=$1 CYCLOPT=$2
ip link set lo up
ip route add 224.0.0.0/4 dev lo
ip route get 239.255.76.67 | grep -q "dev lo" || { echo "FAIL: multicast not routed to lo"; exit 1; }
export LCM_DEFAULT_URL="udpm://239.255.76.67:7667?ttl=0"
WORK=$(mktemp -d /tmp/cyclopt-faults.XXXXXX)
PIDS=()
cleanup() {
  for p in "${PIDS[@]}"; do kill "$p" 2>/dev/null || true; done
  wait 2>/dev/null || true
  umount "$WORK/ro" "$WORK/small" 2>/dev/null || true
  rm -rf "$WORK"
}
trap cleanup EXIT
fail() { echo "FAIL: $*"; exit 1; }

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

# 3. Full disk: a 2 MiB file system; a foot sweep of 3000 points fills it.
mkdir -p "$WORK/small"
mount -t tmpfs -o size=2m tmpfs "$WORK/small"
DB=$WORK/small/results.db
"$CYCLOPTD" --database "$DB" --workers 1 >"$WORK/full.log" 2>&1 &
PIDS+=("$!")
for _ in $(seq 100); do "$CYCLOPT" --timeout 0.5 list >/dev/null 2>&1 && break; sleep 0.1; done
SPEC=$WORK/sweep.json
printf '{"scene": "walker", "task": "foot_sweep", "foot": "P2-shoes-left-HMT", "samples": 200, "sweep": {"parameter": "density", "values": "1:0.01:60"}}' >"$SPEC"
set +e  # watching from the submission on: the disk may be full before a separate watch starts
WATCH=$("$CYCLOPT" submit --spec "$SPEC" --watch --watch-timeout 60 2>/dev/null)
RC=$?
set -e
JOB=$(echo "$WATCH" | sed -n 's/^job \([0-9]*\) queued (request.*/\1/p')
echo "$WATCH" | grep -q "queued: .*could not store a point" || fail "full disk: watcher saw '$WATCH'"
[ "$RC" -eq 2 ] || fail "full disk: watch exit $RC, expected 2"
STORED=$(echo "$WATCH" | sed -n 's/.*: \([0-9]*\) points stored.*/\1/p')
[ "${STORED:-0}" -gt 0 ] || fail "full disk: nothing stored before the disk was full"
kill "${PIDS[-1]}"; wait "${PIDS[-1]}" 2>/dev/null || true
[ "$(sqlite3 "$DB" "PRAGMA integrity_check")" = ok ] || fail "full disk: integrity_check"
ROWS=$(sqlite3 "$DB" "SELECT count(*) FROM solutions WHERE job_id = $JOB")
[ "$ROWS" -ge "$STORED" ] || fail "full disk: $ROWS rows stored, the watcher was told $STORED"
# queued, or still running when even the state change found no room (the watcher was told it is
# re-queued at the next start; recover_interrupted does that).
STATE=$(sqlite3 "$DB" "SELECT state FROM jobs WHERE id = $JOB")
case "$STATE" in queued|running) ;; *) fail "full disk: job state $STATE, expected queued or running" ;; esac
echo "full disk: watcher told '$(echo "$WATCH" | head -c 240)', exit 2; $ROWS points kept, job $STATE, integrity_check ok"
echo PASS
