#!/usr/bin/env bash
# Runs a command against a real cycloptd inside a private network namespace (unshare -n) whose
# loopback carries the multicast route, so no LCM traffic reaches the host; the server signs with
# a key of its own and the command finds the LCM URL in $LCM_DEFAULT_URL, the key file in
# $CYCLOPT_KEY_FILE and the database in $CYCLOPT_DATABASE. Killed after TIMEOUT seconds.
# usage: in_netns.sh TIMEOUT CYCLOPTD COMMAND...     exit: the command's, 77 skipped (no namespace)
set -euo pipefail
if [ "${CYCLOPT_IN_NETNS:-}" != 1 ]; then
  if ! unshare -n true 2>/dev/null; then
    echo "SKIP: cannot create a network namespace (needs root / CAP_SYS_ADMIN)"
    exit 77
  fi
  exec timeout -k 5 "$1" unshare -n env CYCLOPT_IN_NETNS=1 bash "$0" "$@"
fi
shift
CYCLOPTD=$1
shift
ip link set lo up
ip route add 224.0.0.0/4 dev lo
ip route get 239.255.76.67 | grep -q "dev lo" || { echo "FAIL: multicast not routed to lo"; exit 1; }
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
