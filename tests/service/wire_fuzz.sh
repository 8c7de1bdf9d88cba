#!/usr/bin/env bash
# Fuzz test of issue 19 with real processes: cycloptd, a watching `cyclopt` client and, as a
# canary, lcm-logger (liblcm 1.3.1's own receiver) get COUNT hostile datagrams on every channel
# (cyclopt-wire-fuzz: mutated encodings in LC02 datagrams, LC03 fragments with lying headers).
# cycloptd must stay up and answer, the client must still see its job end correctly. Reports
# datagrams sent, the server's peak RSS and what became of lcm-logger. Everything runs inside
# a private network namespace (unshare -n) whose loopback carries the multicast route.
#
# usage: wire_fuzz.sh CYCLOPTD CYCLOPT WIRE_FUZZ COUNT
# exit: 0 pass, 1 fail, 77 skipped (no permission to create a network namespace)
set -euo pipefail

HERE=$(cd "$(dirname "$0")" && pwd)
# shellcheck source=netns.sh
source "$HERE/netns.sh"
netns_enter 100 "-n" "$0" "$@"

CYCLOPTD=$1 CYCLOPT=$2 WIRE_FUZZ=$3 COUNT=$4
netns_loopback_multicast

export LCM_DEFAULT_URL="udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304"
test_workspace wire-fuzz

"$CYCLOPTD" --database "$WORK/results.db" --workers 1 >"$WORK/server.log" 2>&1 &
SERVER=$!
PIDS+=("$SERVER")
for _ in $(seq 100); do "$CYCLOPT" --timeout 0.5 list >/dev/null 2>&1 && break; sleep 0.1; done
"$CYCLOPT" --timeout 0.5 list >/dev/null 2>&1 || fail "server did not come up"
# Without a key file the server warns, once, that anyone on the network can steer it.
[ "$(grep -c "WARNING: no auth_secret_file" "$WORK/server.log")" -eq 1 ] || fail "no single warning about missing authentication"
echo "without a key file: $(grep -o "WARNING: no auth_secret_file.*can submit, cancel" "$WORK/server.log")"
lcm-logger -q -f --lcm-url="$LCM_DEFAULT_URL" "$WORK/canary.lcmlog" >"$WORK/logger.log" 2>&1 &
LOGGER=$!

printf '{"scene": "walker", "task": "foot_sweep", "foot": "P2-shoes-left-HMT", "point_delay_ms": 60, "sweep": {"parameter": "density", "values": "1:1:100"}}' >"$WORK/spec.json"
JOB=$("$CYCLOPT" submit --spec "$WORK/spec.json" | awk '{print $2}')
"$CYCLOPT" watch "$JOB" --watch-timeout 60 >"$WORK/watch.txt" 2>/dev/null &
WATCH=$!
sleep 0.5

T0=$(date +%s.%N)
SENT=$("$WIRE_FUZZ" 239.255.76.67 7667 "$COUNT") || fail "fuzz sender failed"
T1=$(date +%s.%N)
echo "sent $SENT hostile datagrams on 7 channels in $(echo "$T0 $T1" | awk '{printf "%.1f", $2 - $1}') s"
kill -0 "$SERVER" 2>/dev/null || fail "cycloptd died"
"$CYCLOPT" list >/dev/null || fail "cycloptd does not answer after the fuzz"
"$CYCLOPT" submit --foot P2-shoes-left-HMT --sweep density --values 1:1:2 --watch >/dev/null 2>&1 || fail "cycloptd cannot run a job after the fuzz"
echo "cycloptd alive and answering; peak RSS $(awk '/VmHWM/ {printf "%.1f MiB", $2 / 1024}' /proc/$SERVER/status)"
wait "$WATCH" || fail "the watching client failed: $(cat "$WORK/watch.txt")"
grep -q "done" "$WORK/watch.txt" || fail "the watching client did not see its job end: $(cat "$WORK/watch.txt")"
echo "watching client: $(cat "$WORK/watch.txt")"

# The canary: liblcm's receiver against the same datagrams (and then the single one that wraps
# a fragment offset past 2^32).
WHEN="during the fuzz"
if kill -0 "$LOGGER" 2>/dev/null; then
  WHEN="on the single wrapping fragment"
  "$WIRE_FUZZ" 239.255.76.67 7667 1 --only-liblcm-killer >/dev/null
  sleep 0.5
fi
if kill -0 "$LOGGER" 2>/dev/null; then
  echo "liblcm 1.3.1 receiver (lcm-logger): survived"
  kill "$LOGGER"
else
  set +e; wait "$LOGGER"; RC=$?; set -e
  echo "liblcm 1.3.1 receiver (lcm-logger): died $WHEN, exit status $RC ($( [ $RC -gt 128 ] && kill -l $((RC - 128)) ))"
fi
kill -0 "$SERVER" 2>/dev/null || fail "cycloptd died"
kill -TERM "$SERVER"
wait "$SERVER" || fail "cycloptd exited with $? on SIGTERM"
grep -E "cycloptd: (stopping|datagrams)" "$WORK/server.log"
echo "PASS"
