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
