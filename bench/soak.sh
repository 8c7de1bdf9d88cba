#!/usr/bin/env bash
# The soak test of issue 57 (tests/service/service_soak.sh; ctest runs it for 75 s) for MINUTES
# of faults: kill -9 at random times, a full disk, malformed traffic, half of it authenticated,
# while four clients submit small jobs of every kind. Appends its figures, with the CPU model,
# the commit and the machine's load, to bench/results/soak.txt.
#
# usage: bench/soak.sh [BUILD_DIR [MINUTES [SEED]]]   (default build, 30; as root: namespaces)
set -euo pipefail
BUILD=${1:-build} MINUTES=${2:-30}
HERE=$(cd "$(dirname "$0")" && pwd)
OUT=$HERE/results/soak.txt
{
  echo "=== $(date -u '+%Y-%m-%d %H:%M UTC'), $(git -C "$HERE" rev-parse --short HEAD)"
  echo "$(lscpu | grep 'Model name' | sed 's/  */ /g'), $(nproc) cores; load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "\$ service_soak.sh ... $((MINUTES * 60)) ${3:-}"
  bash "$HERE/../tests/service/service_soak.sh" "$BUILD/server/cycloptd" "$BUILD/client/cyclopt" "$BUILD/client/cyclopt-foot" \
    "$BUILD/tests/service/cyclopt-wire-fuzz" "$BUILD/tests/service/cyclopt-bad-sender" $((MINUTES * 60)) ${3:+"$3"} && rc=0 || rc=$?
  echo "load average at end: $(cut -d' ' -f1-3 /proc/loadavg)"
  exit "$rc"
} 2>&1 | tee -a "$OUT"
