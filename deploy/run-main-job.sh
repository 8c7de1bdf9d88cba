#!/usr/bin/env bash
# Main job of the service (README, quick start): what a rolling foot saves against point feet.
# Starts cycloptd with a fresh database in out/service/ and submits a foot_comparison
# (docs/foot-comparison.md): energy-optimal gaits of FOOT and of point feet (Table D.1) over SPEEDS,
# each found by the chapter-9 sweep (a multistart of STARTS random starts at SEED_SPEED, continued
# over the grid). It watches the job, prints each foot's mean f_mech and the saving, then solves the
# rolling foot's gait at SEED_SPEED again from the comparison's optimum (an optimise job started
# from that stored point) so that its gait can be drawn. Writes the pictures (PNG and SVG) to
# out/pictures/ - f_mech of both feet over speed, the foot's outline, two steps of the rolling
# foot's gait - and the two jobs' HTML reports to out/report.html (the comparison) and
# out/gait_report.html (the gait, animated).
# LCM traffic stays inside a private network namespace created here (needs root): nothing goes
# on the host's network. Run after the build (cmake --build build).
# Environment: FOOT (preset or foot JSON file, default P2-shoes-left-HMT, the seed's best fitted
# foot), SPEEDS (lo:step:hi, m/s, default 0.8:0.1:1.4), STARTS (default 20, as the seed's
# multistart), SEED_SPEED (a speed of SPEEDS, default 1.2), GIANT_SWING=1 to add the giant swing's
# stroboscope (about 70 s of CPU).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${BUILD:-build}
FOOT=${FOOT:-P2-shoes-left-HMT}
SPEEDS=${SPEEDS:-0.8:0.1:1.4}
SEED_SPEED=${SEED_SPEED:-1.2}
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
CYCLOPT="$BUILD/client/cyclopt"
"$BUILD/server/cycloptd" --database "$OUT/cyclopt.db" 2>"$OUT/cycloptd.log" &
SERVER=$!
trap 'kill -TERM $SERVER 2>/dev/null; wait $SERVER' EXIT
FOOT_JSON=$([ -f "$FOOT" ] && cat "$FOOT" || printf '"%s"' "$FOOT")
cat > "$OUT/comparison.json" <<SPEC
{"scene": "walker", "task": "foot_comparison", "name": "$FOOT against point feet, $SPEEDS m/s",
 "feet": [$FOOT_JSON], "reference": "point", "speeds": "$SPEEDS", "objective": "f_mech",
 "multistart": {"starts": ${STARTS:-20}}, "continuation": {"seed_speeds": $SEED_SPEED}}
SPEC
# An incomplete job (exit 5: some speeds without a converged gait) still gets its table, pictures
# and report; the script then ends with that exit code.
# Submits a spec file, shows the server's answer and sets JOB to the new job's id.
submit() { local answer; answer=$("$CYCLOPT" submit --spec "$1"); echo "$answer"; JOB=$(grep -o '^job [0-9]*' <<<"$answer" | grep -o '[0-9]*'); }
submit "$OUT/comparison.json"
COMPARISON=$JOB
OUTCOME=0
"$CYCLOPT" watch "$COMPARISON" || OUTCOME=$?
[ "$OUTCOME" -eq 0 ] || [ "$OUTCOME" -eq 5 ] || exit "$OUTCOME"
echo
"$CYCLOPT" query "$COMPARISON"
# The rolling foot's optimum at the seed speed, solved again from the comparison's stored point
# (curve 2: the first compared foot; docs/walker-jobs.md, "start") so that its gait is drawn.
POINT=$("$CYCLOPT" query "$COMPARISON" --what solutions --csv --wide |
  awk -F, -v v="$SEED_SPEED" 'NR > 1 && $1 == 2 && $3 + 0 == v + 0 { print $2; exit }')
cat > "$OUT/gait.json" <<SPEC
{"scene": "walker", "task": "optimise", "name": "$FOOT at $SEED_SPEED m/s", "foot": $FOOT_JSON,
 "speed": $SEED_SPEED, "objective": "f_mech", "start": {"job": $COMPARISON, "curve": 2, "point": ${POINT:-0}}}
SPEC
submit "$OUT/gait.json"
GAIT=$JOB
"$CYCLOPT" watch "$GAIT"
echo
echo "database: $OUT/cyclopt.db (read it with: $CYCLOPT query $COMPARISON --db $OUT/cyclopt.db)"
"$CYCLOPT" plot foot-comparison --job "$COMPARISON" --db "$OUT/cyclopt.db" --out "$PICTURES"
"$CYCLOPT" plot stroboscope --job "$GAIT" --db "$OUT/cyclopt.db" --out "$PICTURES"
"$CYCLOPT" report "$COMPARISON" --db "$OUT/cyclopt.db" --out out/report.html
"$CYCLOPT" report "$GAIT" --db "$OUT/cyclopt.db" --out out/gait_report.html
if [ "${GIANT_SWING:-0}" != 0 ]; then
  "$BUILD/client/cyclopt-giant-swing" --preset single_swing > out/giant_swing.json
  "$CYCLOPT" plot giant-swing --result out/giant_swing.json --out "$PICTURES"
fi
echo "pictures: $PICTURES/*.png (SVG beside each); reports: out/report.html, out/gait_report.html"
[ "$OUTCOME" -eq 0 ] || echo "the comparison ended incomplete (exit $OUTCOME): see the outcome above and in the report"
exit "$OUTCOME"
