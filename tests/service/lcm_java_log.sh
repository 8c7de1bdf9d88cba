#!/usr/bin/env bash
# cyclopt's Java LCM types (proto/CMakeLists.txt, lcm-gen -j) decode what lcm-logger records of a
# real session (issue 17 item 10): a server, a job submitted, watched, queried and cancelled; every
# event of every channel decodes as its type. Runs inside a private network namespace (unshare -n)
# whose loopback carries the multicast route, so no datagram leaves it.
#
# usage: lcm_java_log.sh CYCLOPTD CYCLOPT CLASSPATH
# exit: 0 pass, 1 fail, 77 skipped (no permission to create a network namespace)
set -euo pipefail

HERE=$(cd "$(dirname "$0")" && pwd)
# shellcheck source=netns.sh
source "$HERE/netns.sh"
netns_enter 110 "-n" "$0" "$@"

CYCLOPTD=$1 CYCLOPT=$2 CP=$3
netns_loopback_multicast

URL="udpm://239.255.76.67:7667?ttl=0"
test_workspace java-log

lcm-logger -q -f --channel='CYCLOPT_.*' --lcm-url="$URL" "$WORK/cyclopt.lcmlog" &
LOGGER=$!
PIDS+=("$LOGGER")
"$CYCLOPTD" --database "$WORK/results.db" --lcm-url "$URL" --workers 1 >"$WORK/server.log" 2>&1 &
SERVER=$!
PIDS+=("$SERVER")
for _ in $(seq 100); do "$CYCLOPT" --lcm-url "$URL" --timeout 0.5 list >/dev/null 2>&1 && break; sleep 0.1; done
printf '{"scene": "walker", "task": "optimise", "foot": "point", "speed": 1.0}' >"$WORK/job.json"
"$CYCLOPT" --lcm-url "$URL" submit --spec "$WORK/job.json" --watch >"$WORK/submit.txt" 2>&1 || fail "job did not run: $(cat "$WORK/submit.txt")"
"$CYCLOPT" --lcm-url "$URL" query 1 >/dev/null || fail "query"
"$CYCLOPT" --lcm-url "$URL" cancel 1 >/dev/null 2>&1 || true  # already done: rejected, but sent and answered
kill -TERM "$SERVER"; wait "$SERVER" || true
kill -INT "$LOGGER"; wait "$LOGGER" 2>/dev/null || true

java -cp "$CP" CycloptLogDecode "$WORK/cyclopt.lcmlog" >"$WORK/decoded.txt" || fail "undecodable events: $(tr '\n' ' ' <"$WORK/decoded.txt")"
while read -r channel type; do
  grep -q "^$channel $type [1-9]" "$WORK/decoded.txt" || fail "no $channel event decoded as $type: $(tr '\n' ' ' <"$WORK/decoded.txt")"
done <<'TYPES'
CYCLOPT_SUBMIT job_submit_t
CYCLOPT_ACK job_ack_t
CYCLOPT_PROGRESS job_progress_t
CYCLOPT_DONE job_done_t
CYCLOPT_QUERY query_request_t
CYCLOPT_QUERY_REPLY query_reply_t
CYCLOPT_CANCEL job_cancel_t
TYPES
[ "$(awk '{print $1}' "$WORK/decoded.txt" | sort | uniq -d)" = "" ] || fail "a channel carries several types: $(tr '\n' ' ' <"$WORK/decoded.txt")"
echo "decoded with the Java types: $(tr '\n' ' ' <"$WORK/decoded.txt")"
echo PASS
