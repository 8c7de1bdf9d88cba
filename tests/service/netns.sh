# Sourced by the multi-process tests and benchmarks: run a script inside namespaces of its own,
# where LCM multicast stays on the namespace's loopback (the network rule of DEVELOPERS.md).
#
#   netns_enter SECONDS "FLAGS" "$0" "$@"   re-runs the script under `unshare FLAGS` (e.g. "-n" or
#                                           "-n -m") within a timeout of SECONDS; returns when
#                                           already inside; exits 77 when the namespaces cannot be
#                                           made (needs root / CAP_SYS_ADMIN)
#   netns_loopback_multicast                lo up, 224.0.0.0/4 routed to it; refuses to go on
#                                           unless multicast stays on this namespace's loopback
#   wait_for SECONDS COMMAND...             polls COMMAND every 0.05 s; fails after SECONDS
#   test_workspace NAME                     WORK, a fresh /tmp/cyclopt-NAME.XXXXXX; PIDS, the processes
#                                           to kill at exit; an EXIT trap that kills them, runs
#                                           on_cleanup if the script defines one, and removes WORK
#   fail MESSAGE...                         prints FAIL: MESSAGE and the tail of $WORK/server.log, exits 1

netns_enter() {
  local seconds=$1 flags=$2
  shift 2
  [ "${CYCLOPT_IN_NETNS:-}" = 1 ] && return 0
  # shellcheck disable=SC2086  # FLAGS are words
  if ! unshare $flags true 2>/dev/null; then
    echo "SKIP: cannot create the namespaces (unshare $flags needs root / CAP_SYS_ADMIN)"
    exit 77
  fi
  local private=()
  case " $flags " in *" -m "*) private=(--propagation private) ;; esac
  # shellcheck disable=SC2086
  exec timeout -k 5 "$seconds" unshare $flags "${private[@]}" env CYCLOPT_IN_NETNS=1 bash "$@"
}

netns_loopback_multicast() {
  [ "${CYCLOPT_IN_NETNS:-}" = 1 ] || { echo "FAIL: not inside a namespace of this test"; exit 1; }
  ip link set lo up
  ip route add 224.0.0.0/4 dev lo
  ip route get 239.255.76.67 | grep -q "dev lo" || { echo "FAIL: multicast not routed to lo"; exit 1; }
  [ "$(ip -o link show | grep -vc ': lo:')" -eq 0 ] || { echo "FAIL: the namespace has other interfaces"; exit 1; }
}

wait_for() {
  local deadline=$(($(date +%s) + $1))
  shift
  until "$@"; do
    [ "$(date +%s)" -lt "$deadline" ] || return 1
    sleep 0.05
  done
}

test_workspace() {
  WORK=$(mktemp -d "/tmp/cyclopt-$1.XXXXXX")
  PIDS=()
  trap workspace_cleanup EXIT
}

workspace_cleanup() {
  for p in "${PIDS[@]}"; do kill "$p" 2>/dev/null || true; done
  wait 2>/dev/null || true
  if declare -F on_cleanup >/dev/null; then on_cleanup; fi
  rm -rf "$WORK"
}

fail() {
  echo "FAIL: $*"
  [ -f "$WORK/server.log" ] && tail -20 "$WORK/server.log"
  exit 1
}
