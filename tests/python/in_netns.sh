#!/usr/bin/env bash
# Runs a command against a real cycloptd inside a private network namespace (unshare -n) whose
# loopback carries the multicast route, so no LCM traffic reaches the host; the server signs with
# a key of its own and the command finds the LCM URL in $LCM_DEFAULT_URL, the key file in
# $CYCLOPT_KEY_FILE and the database in $CYCLOPT_DATABASE. Killed after TIMEOUT seconds.
# usage: in_netns.sh TIMEOUT CYCLOPTD COMMAND...     exit: the command's, 77 skipped (no namespace)
set -euo pipefail
. "$(dirname "$0")/../service/netns.sh"
netns_enter "$1" "-n" "$0" "$@"
shift
CYCLOPTD=$1
shift
netns_loopback_multicast
export LCM_DEFAULT_URL="udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304"
WORK=$(mktemp -d /tmp/cyclopt-python.XXXXXX)
trap 'kill $SERVER 2>/dev/null; wait 2>/dev/null; rm -rf "$WORK"' EXIT
printf 'python-test %s\n' "$(head -c 32 /dev/urandom | od -An -tx1 | tr -d ' \n')" >"$WORK/keys"
chmod 600 "$WORK/keys"
export CYCLOPT_KEY_FILE="$WORK/keys" CYCLOPT_DATABASE="$WORK/results.db"
printf '{"database": "%s", "workers": 1, "progress_hz": 5, "auth_secret_file": "%s"}' "$CYCLOPT_DATABASE" "$CYCLOPT_KEY_FILE" \
  >"$WORK/cycloptd.json"
"$CYCLOPTD" --config "$WORK/cycloptd.json" >"$WORK/server.log" 2>&1 &
SERVER=$!
set +e
"$@"
status=$?
[ $status -eq 0 ] || { echo "server log:"; tail -20 "$WORK/server.log"; }
exit $status
