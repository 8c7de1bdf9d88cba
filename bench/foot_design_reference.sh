#!/usr/bin/env bash
# Issue 51 acceptance 6: the rho 10 design study of seed 001 section 10.2 as a reference that every
# host of the default build's instruction-set level must reproduce line for line. Runs
# `foot_design_bench 10 20 0.3:0.1:2.3 20` (~25 min on 2 cores), replaces every duration ("12.3 s")
# by "T s" and compares with bench/results/foot_design_reference.txt, all but its comment lines and
# the bench's first line (which names the CPU); "write" stores the run as the new reference instead.
# Two things in the output follow the clock, not the numerics, and are left out of the comparison:
# the padding before a duration (" 9.2 s" against "10.0 s") and the step line announcing that the
# design's sweep still runs when the low-speed design's has ended (studies/foot_design.cpp).
# usage: foot_design_reference.sh BUILD_DIR [write]
set -euo pipefail
trap 'rm -f /tmp/foot_design_reference.$$' EXIT
BUILD=$(realpath "$1") HERE=$(dirname "$(realpath "$0")")
REFERENCE=$HERE/results/foot_design_reference.txt
grep -q 'CYCLOPT_ARCH:STRING=x86-64-v3' "$BUILD/CMakeCache.txt" ||
  { echo "the reference is the default build's (CYCLOPT_ARCH x86-64-v3); $BUILD is another level"; exit 2; }
timeless() { sed -E 's/ +T s\b/ T s/g' | grep -v -- "(the low-speed design's has ended)\$"; }
lscpu | grep "Model name"
start=$(date +%s)
"$BUILD/bench/foot_design_bench" 10 20 0.3:0.1:2.3 20 | sed -E 's/[0-9]+\.[0-9]+ s\b/T s/g' > /tmp/foot_design_reference.$$
echo "run: $(( $(date +%s) - start )) s"
if [ "${2:-}" = write ]; then
  { grep '^#' "$REFERENCE" 2>/dev/null || true; cat /tmp/foot_design_reference.$$; } > "$REFERENCE.new"
  mv "$REFERENCE.new" "$REFERENCE"
  echo "written: $REFERENCE"
elif diff <(grep -v '^#' "$REFERENCE" | tail -n +2 | timeless) <(tail -n +2 /tmp/foot_design_reference.$$ | timeless); then
  echo "identical to the reference, line for line (durations aside)"
else
  echo "DIFFERS from the reference (lines above: < reference, > this host)"; exit 1
fi
