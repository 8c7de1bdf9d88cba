#!/usr/bin/env bash
# `cyclopt top --once`, `list` and `status` against a real cycloptd (issue 53): with a done, a
# running and a queued job, top at 80 columns shows every job's state, progress and best value,
# list fits 120 columns without request ids, status prints ISO 8601 times. Inside a private network
# namespace (unshare -n) whose loopback carries the multicast route; killed after 60 s.
# usage: fleet_views.sh CYCLOPTD CYCLOPT     exit: 0 pass, 1 fail, 77 skipped (no namespace)
set -euo pipefail
. "$(dirname "$0")/../service/netns.sh"
netns_enter 60 "-n" "$0" "$@"
CYCLOPTD=$1 CYCLOPT=$2
netns_loopback_multicast
export LCM_DEFAULT_URL="udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304"
WORK=$(mktemp -d /tmp/cyclopt-fleet.XXXXXX)
trap 'kill $SERVER 2>/dev/null; wait 2>/dev/null; rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*"; tail -5 "$WORK/server.log"; exit 1; }
printf '{"database": "%s/results.db", "workers": 1, "progress_hz": 5}' "$WORK" >"$WORK/cycloptd.json"
"$CYCLOPTD" --config "$WORK/cycloptd.json" >"$WORK/server.log" 2>&1 &
SERVER=$!
for _ in $(seq 100); do "$CYCLOPT" --timeout 0.5 list >/dev/null 2>&1 && break; sleep 0.1; done

# 1: a small point-foot sweep, watched to its end (it has a best objective).
echo '{"scene": "walker", "task": "sweep", "name": "a point-foot sweep with a long name", "foot": "point",
  "speeds": "0.9:0.1:1.1", "multistart": {"starts": 2, "seed": 3, "scale": 0.02}, "continuation": {"seed_speeds": 1.0}}' >"$WORK/sweep.json"
"$CYCLOPT" submit --spec "$WORK/sweep.json" --watch >/dev/null 2>&1 || fail "the sweep did not finish"
# 2: running for a while, 3: queued behind it (one worker).
echo '{"scene": "walker", "task": "foot_sweep", "name": "slow", "foot": "P2-shoes-left-HMT", "point_delay_ms": 200,
  "sweep": {"parameter": "density", "values": "1:1:200"}}' >"$WORK/slow.json"
"$CYCLOPT" submit --spec "$WORK/slow.json" >/dev/null
"$CYCLOPT" submit --spec "$WORK/slow.json" --request-id queued-one >/dev/null
for _ in $(seq 100); do [ "$("$CYCLOPT" list --json | grep -c '"running"')" -ge 1 ] && break; sleep 0.1; done
sleep 1.5  # a progress record of the running job

COLUMNS=80 "$CYCLOPT" top --once >"$WORK/top.txt" || fail "top --once failed"
cat "$WORK/top.txt"
awk 'length($0) > 80 { print "FAIL: line of " length($0) " characters: " $0; bad = 1 } END { exit bad }' "$WORK/top.txt" || exit 1
# Header, then one line per job: ID STATE PROG BEST first.
sed -n 2p "$WORK/top.txt" | grep -Eq '^ID +STATE +PROG +BEST' || fail "top's header: $(sed -n 2p "$WORK/top.txt")"
line() { awk -v id="$1" 'NR > 2 && $1 == id' "$WORK/top.txt"; }
line 1 | grep -Eq '^1 +done +100% +0\.[0-9]+' || fail "job 1: $(line 1)"
line 2 | grep -Eq '^2 +running +(>=)?[0-9]+% +[-0-9.e]+' || fail "job 2: $(line 2)"
line 3 | grep -Eq '^3 +queued +- +-' || fail "job 3: $(line 3)"

COLUMNS=120 "$CYCLOPT" list >"$WORK/list.txt"
cat "$WORK/list.txt"
awk 'length($0) > 120 { print "FAIL: list line of " length($0) " characters"; bad = 1 } END { exit bad }' "$WORK/list.txt" || exit 1
head -1 "$WORK/list.txt" | grep -Eq '^ID +NAME +KIND +FOOT +STATE +PROG +BEST +RUN +SUBMITTED' || fail "list's header"
grep -q queued-one "$WORK/list.txt" && fail "list shows request ids without --wide"
"$CYCLOPT" list --wide | grep -q queued-one || fail "list --wide lacks the request id"
"$CYCLOPT" status 2 >"$WORK/status.txt"
grep -Eq '^submitted_at +[0-9]{4}-[0-9]{2}-[0-9]{2}T[0-9]{2}:[0-9]{2}:[0-9]{2}[+-][0-9]{2}:[0-9]{2}$' "$WORK/status.txt" \
  || fail "status times: $(grep _at "$WORK/status.txt")"
grep -Eq '^progress +(>=)?[0-9]+%' "$WORK/status.txt" || fail "status shows no progress: $(cat "$WORK/status.txt")"
"$CYCLOPT" cancel 2 >/dev/null; "$CYCLOPT" cancel 3 >/dev/null
echo "PASS"
