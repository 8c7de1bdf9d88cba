#!/usr/bin/env bash
# Issue 51 acceptance 2, as far as one host can check it: the default build's binary gives the same
# bits on other processors of its level. The only way one binary's numbers can follow the processor
# is a choice made at run time from CPUID: glibc's libm variants, a BLAS that dispatches, Eigen's
# blocking of matrix products by the cache sizes (fixed by EIGEN_NO_CPUID, CMakeLists.txt); the
# binary's own code is fixed by -march=x86-64-v3. qemu-x86_64 (Debian's qemu-user, TCG) runs the
# binary on an emulated processor with its own CPUID: another vendor, model, ISA level and cache
# sizes (ld.so --list-diagnostics: isa_1 0x7 = x86-64-v3, no AVX-512 on the models below).
# Each solve runs natively and under each model; its "bits:" line (walker_solver_bench ... bits:
# hexadecimal f, KKT error and violation, FNV-1a of z) must be identical. A control model of the
# level below (Nehalem, x86-64-v2) must stop with SIGILL: the emulation enforces the model.
# TCG emulates AVX2 ~300x slower than the hardware: the SQP solve (2.6 s natively) takes ~20 min
# per model, the Ipopt solve's 10 iterations ~5 min; the models run side by side.
# usage: other_processors.sh BUILD_DIR [CPU_MODEL ...]   (default EPYC-Rome Haswell)
set -euo pipefail
BUILD=$(realpath "$1"); shift
[ $# -gt 0 ] && MODELS=("$@") || MODELS=(EPYC-Rome Haswell)
command -v qemu-x86_64 >/dev/null || { echo "needs qemu-x86_64 (apt-get install qemu-user)"; exit 2; }
grep -q 'CYCLOPT_ARCH:STRING=x86-64-v3' "$BUILD/CMakeCache.txt" ||
  { echo "checks the default build (CYCLOPT_ARCH x86-64-v3); $BUILD is another level"; exit 2; }
BENCH=$BUILD/bench/walker_solver_bench
WORK=$(mktemp -d); trap 'rm -rf "$WORK"' EXIT
# The SQP solve to its optimum (Table 6.2 options), Ipopt's first iterations (MUMPS and the BLAS).
SOLVES=("P2-shoes-left-HMT 1.3 sqp 3000" "P2-shoes-left-HMT 1.3 ipopt 10")
lscpu | grep -E "Model name"
# What glibc sees of a processor: vendor, ISA level, L1d and L2 sizes ($@: qemu-x86_64 -cpu MODEL, or nothing).
cpu_features() {
  "$@" /lib64/ld-linux-x86-64.so.2 --list-diagnostics 2>/dev/null |
    grep -E 'isa_1=|basic.kind=|level1_dcache_size=|level2_cache_size=' | tr '\n' ' '
}
echo "host: $(cpu_features)"
bits() { grep '^bits:' || echo "no result"; }
for model in "${MODELS[@]}"; do echo "$model: $(cpu_features qemu-x86_64 -cpu "$model")"; done
status=0
declare -A native
for solve in "${SOLVES[@]}"; do
  # shellcheck disable=SC2086
  native[$solve]=$("$BENCH" $solve bits | bits)
  echo "$solve: native $(printf '%-9s' '') ${native[$solve]}"
done
# One background run per model (TCG uses one core each), the lines printed in a fixed order.
for model in "${MODELS[@]}"; do
  (for solve in "${SOLVES[@]}"; do
     start=$(date +%s)
     # shellcheck disable=SC2086
     echo "$(qemu-x86_64 -cpu "$model" "$BENCH" $solve bits 2>/dev/null | bits)|$(( $(date +%s) - start ))"
   done > "$WORK/$model") &
done
wait
for model in "${MODELS[@]}"; do
  i=0
  while IFS='|' read -r emulated seconds; do
    solve=${SOLVES[$i]}; i=$((i + 1))
    verdict=identical; [ "$emulated" = "${native[$solve]}" ] || { verdict=DIFFERS; status=1; }
    echo "$solve: $(printf '%-9s' "$model") $emulated  ($verdict, $seconds s emulated)"
  done < "$WORK/$model"
done
if qemu-x86_64 -cpu Nehalem "$BENCH" P2-shoes-left-HMT 1.3 sqp 1 bits >/dev/null 2>&1; then
  echo "control: the x86-64-v2 model Nehalem ran the x86-64-v3 binary - the emulation does not enforce its model"
  status=1
else
  echo "control: the x86-64-v2 model Nehalem stops the x86-64-v3 binary (exit $?), as it must"
fi
exit $status
