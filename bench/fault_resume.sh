#!/usr/bin/env bash
# What three kill -9 cost during a P2-shoes-left-HMT speed sweep (issue 57, acceptance 2: at most
# 10 % extra CPU, rows identical): tests/service/sweep_resume.sh with the foot, 0.3:0.1:2.3 m/s and
# 20 multistart starts per seed speed (speed_sweep_bench's sweep), each attempt killed once it has
# recorded a quarter of the uninterrupted run's journal entries. CPU time (user + sys of cycloptd,
# whose worker threads compute the job), not wall time: the machine is shared with other builds.
# Appends the output, with the CPU model and the load, to bench/results/fault_resume.txt.
#
# usage: bench/fault_resume.sh BUILD_DIR        (as root: the script uses a network namespace)
set -euo pipefail
BUILD=${1:-build}
HERE=$(cd "$(dirname "$0")" && pwd)
OUT=$HERE/results/fault_resume.txt
{
  echo "=== $(date -u '+%Y-%m-%d %H:%M UTC'), $(git -C "$HERE" rev-parse --short HEAD)"
  echo "$(lscpu | grep 'Model name' | sed 's/  */ /g'), $(nproc) cores; load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "\$ sweep_resume.sh cycloptd cyclopt 20 0.25 P2-shoes-left-HMT 0.3:0.1:2.3"
  # Caps raised so that neither the iteration nor the time limit can end the measured sweep.
  CYCLOPTD_ARGS="--max-job-iterations 1000000000 --max-job-seconds 604800" CYCLOPT_RESUME_TIMEOUT=14400 bash "$HERE/../tests/service/sweep_resume.sh" "$BUILD/server/cycloptd" "$BUILD/client/cyclopt" \
    20 0.25 P2-shoes-left-HMT 0.3:0.1:2.3
  echo "load average at end: $(cut -d' ' -f1-3 /proc/loadavg)"
} 2>&1 | tee -a "$OUT"
