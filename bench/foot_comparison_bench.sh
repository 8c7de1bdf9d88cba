#!/bin/bash
# The 16-foot comparison of seed 001 section 9.2 as one foot_comparison job (issue 16 item 5,
# acceptance 4): runs build/bench/foot_comparison_bench and keeps its table in
# bench/results/foot_comparison_bench.txt and its figures and job document in
# bench/results/foot_comparison/ (progress.log: which foot ran when). The seed's setting is the default; a reduced one for a loaded
# machine, e.g.:
#   bash bench/foot_comparison_bench.sh                                  # seed: 0.3:0.1:2.3, 20 starts, P = 200
#   SPEEDS=0.8:0.5:1.8 STARTS=2 SEED_SPEEDS=1.3 POINTS=100 bash bench/foot_comparison_bench.sh
set -euo pipefail
cd "$(dirname "$0")/.."
SPEEDS=${SPEEDS:-0.3:0.1:2.3}
STARTS=${STARTS:-20}
SEED_SPEEDS=${SEED_SPEEDS:-0.3,1.3,2.3}
POINTS=${POINTS:-200}
OUT=${OUT:-bench/results/foot_comparison}
RESULT=${RESULT:-bench/results/foot_comparison_bench.txt}
mkdir -p "$OUT"
{
  echo "== $(date -u '+%Y-%m-%d %H:%M UTC'): SPEEDS=$SPEEDS STARTS=$STARTS SEED_SPEEDS=$SEED_SPEEDS POINTS=$POINTS ${FEET:+FEET=$FEET}"
  /usr/bin/time -o "$OUT/time.txt" -f "process: %e s wall, %U s user, %S s system, %M KiB max RSS" \
    build/bench/foot_comparison_bench "$SPEEDS" "$STARTS" "$SEED_SPEEDS" "$POINTS" "$OUT" ${FEET:+"$FEET"} \
    2> "$OUT/progress.log"
  cat "$OUT/time.txt"
  echo
} | tee -a "$RESULT"
