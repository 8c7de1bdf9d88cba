#!/usr/bin/env bash
# Main job of the service (README, "The service" and "Pictures and reports"): starts cycloptd with a
# fresh database in out/service/, submits a walker speed sweep (optimal gaits of FOOT over SPEEDS;
# default: point feet, Table D.1, the quickest; rolling feet such as FOOT=P2-shoes-left-HMT take
# minutes, bench/results/speed_sweep_bench.txt), watches it, prints the result table, then writes the
# pictures (PNG and SVG) to out/pictures/ and the job's HTML report to out/report.html, and the
# giant swing stroboscope of the seed's single swing beside them.
# LCM traffic stays inside a private network namespace created here (needs root): nothing goes
# on the host's network. Run after the build (cmake --build build).
# Environment: FOOT (preset or foot JSON file), SPEEDS (lo:step:hi, m/s), STARTS (multistart runs
# at the first speed, default 2), GIANT_SWING=0 to skip the giant swing (about 70 s of CPU).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${BUILD:-build}
FOOT=${FOOT:-point}
SPEEDS=${SPEEDS:-0.8:0.2:1.4}
OUT=out/service
PICTURES=out/pictures
if [ "${CYCLOPT_IN_NETNS:-}" != 1 ]; then
  mkdir -p "$OUT"
  rm -f "$OUT"/cyclopt.db "$OUT"/cyclopt.db-wal "$OUT"/cyclopt.db-shm
  exec unshare -n env CYCLOPT_IN_NETNS=1 bash "$0" "$@"
fi
ip link set lo up
ip route add 224.0.0.0/4 dev lo
export LCM_DEFAULT_URL="udpm://239.255.76.67:7667?ttl=0"
"$BUILD/server/cycloptd" --database "$OUT/cyclopt.db" 2>"$OUT/cycloptd.log" &
SERVER=$!
trap 'kill -TERM $SERVER 2>/dev/null; wait $SERVER' EXIT
# The chapter-9 sweep (multistart at a seed speed, continuation over the grid, best point per
# speed), kept small so the demo takes a few minutes: STARTS random starts at the first speed.
FOOT_JSON=$([ -f "$FOOT" ] && cat "$FOOT" || printf '"%s"' "$FOOT")
cat > "$OUT/sweep.json" <<SPEC
{"scene": "walker", "task": "sweep", "name": "optimal gaits of $FOOT over $SPEEDS m/s",
 "foot": $FOOT_JSON, "speeds": "$SPEEDS", "objective": "f_mech",
 "multistart": {"starts": ${STARTS:-2}}, "continuation": {"seed_speeds": ${SPEEDS%%:*}}}
SPEC
# An incomplete job (exit 5: some speeds without a converged gait) still gets its table, pictures
# and report; the script then ends with that exit code.
OUTCOME=0
"$BUILD/client/cyclopt" submit --spec "$OUT/sweep.json" --watch || OUTCOME=$?
[ "$OUTCOME" -eq 0 ] || [ "$OUTCOME" -eq 5 ] || exit "$OUTCOME"
JOB=$("$BUILD/client/cyclopt" list --json | grep -o '"id": [0-9]*' | tail -1 | grep -o '[0-9]*')
"$BUILD/client/cyclopt" query "$JOB"
echo "database: $OUT/cyclopt.db (read it with: $BUILD/client/cyclopt query $JOB --db $OUT/cyclopt.db)"
"$BUILD/client/cyclopt" plot all --job "$JOB" --db "$OUT/cyclopt.db" --out "$PICTURES"
"$BUILD/client/cyclopt" report "$JOB" --db "$OUT/cyclopt.db" --out out/report.html
if [ "${GIANT_SWING:-1}" != 0 ]; then
  "$BUILD/client/cyclopt-giant-swing" --preset single_swing > out/giant_swing.json
  "$BUILD/client/cyclopt" plot giant-swing --result out/giant_swing.json --out "$PICTURES"
fi
echo "pictures: $PICTURES/*.png (SVG beside each); report: out/report.html (one self-contained page)"
[ "$OUTCOME" -eq 0 ] || echo "the job ended incomplete (exit $OUTCOME): see the outcome above and in the report"
exit "$OUTCOME"
