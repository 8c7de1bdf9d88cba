#!/bin/bash
# cyclopt-foot synth / fit end to end (issue 20 items 3-5, issue 56): synthetic trials of a
# preset are written as .trc and CSV, fitted (figures, saved foot usable by cyclopt-foot --foot);
# a trial whose only stance the recording cuts is refused (exit 2); the excerpts of OpenSim's
# recordings in data/ fit with their stances, spreads and figures; a malformed file is rejected
# with exit code 2 and FILE:LINE:COLUMN.
set -euo pipefail
foot_cli=$1
data=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

"$foot_cli" synth --preset P1-shoes-left-HMT --trials 3 --noise 0 --swing 0.1 --out "$dir/trials" > /dev/null
"$foot_cli" fit "$dir"/trials/trial{1,2,3}.csv --json --no-toe-bound --plot-dir "$dir/plots" --save-foot "$dir/foot.json" > "$dir/fit.json"
python3 - "$dir/fit.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
truth = {"h_F": 0.1027, "l_HA": 0.0948, "l_HM": 0.2826, "l_MT": 0.0589}
assert r["hmt"]["converged"], r["hmt"]["message"]
for p in r["hmt"]["parameters"]:
    if p["name"] in truth:
        assert abs(p["value"] / truth[p["name"]] - 1) < 1e-6, (p["name"], p["value"])
        assert p["boundary_spread"] is not None and p["stride_spread"] is not None, p
assert all(s["rule"] == "force Fz" and s["fitted"] for t in r["trials"] for s in t["stances"]), r["trials"]
assert r["hmt"]["rms"] <= r["hm"]["rms"], (r["hmt"]["rms"], r["hm"]["rms"])
assert r["hmt"]["spread_refits"] == 3 + 80, r["hmt"]["spread_refits"]  # leave one out; every 5 ms frame inwards: 9 x 9 but (0, 0)
PY
for f in fit_stances_1 fit_stances_3 fit_hm_ankle fit_hm_outline fit_hmt_ankle fit_hmt_outline; do
  test -s "$dir/plots/$f.png" && test -s "$dir/plots/$f.svg"
done
"$foot_cli" --foot "$dir/foot.json" > /dev/null

# The .trc trials (stances from the kinematics: .trc has no force column).
"$foot_cli" fit "$dir"/trials/trial{1,2,3}.trc --model HMT --no-toe-bound --no-spread > "$dir/fit_trc.txt"
grep -q "HMT fit (eq. 4.21): converged" "$dir/fit_trc.txt"
grep -q "kinematics: fitted" "$dir/fit_trc.txt"

# The same trials as the inline ankle tracks of a foot_fit job spec (service/foot_fit_kind.hpp).
"$foot_cli" fit "$dir"/trials/trial{1,2,3}.csv --job-spec "$dir/job.json" 2> /dev/null
python3 - "$dir/job.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
assert s["task"] == "foot_fit" and len(s["trials"]) == 3, s.keys()
assert all(len(t["x"]) == len(t["z"]) >= 10 for t in s["trials"])
PY

# A trial that starts and ends loaded (no swing): its one stance is cut, nothing is fitted.
"$foot_cli" synth --preset P1-shoes-left-HMT --trials 1 --noise 0 --swing 0 --format csv --out "$dir/cut" > /dev/null
set +e
"$foot_cli" fit "$dir/cut/trial1.csv" > "$dir/cut.txt" 2> "$dir/cut_err.txt"
code=$?
set -e
test "$code" -eq 2
grep -q "no complete stance to fit" "$dir/cut_err.txt"
grep -q "refused: cut by the start of the force recording" "$dir/cut_err.txt"
! grep -q "converged" "$dir/cut.txt"

# OpenSim's test_walking (z up, gaps stored as 0.0): the right foot's second stance runs into the
# end of the malleoli's data and is refused; the first is fitted without a hand-given interval
# (its boundary spread on the 10 ms grid: 80 refits instead of every frame's 440, for time).
"$foot_cli" fit "$data/test_walking_ankles.trc" --marker RLMAL --marker RMMAL --boundary-steps 4 --plot-dir "$dir/tw" > "$dir/tw.txt"
grep -q "vertical axis detected: z" "$dir/tw.txt"
grep -q "stance 1: .*kinematics: fitted" "$dir/tw.txt"
grep -q "stance 2: .*REFUSED, cut by the end of the ankle markers' data" "$dir/tw.txt"
grep -q "HMT fit (eq. 4.21): converged" "$dir/tw.txt"
test -s "$dir/tw/fit_stances_1.png"
# The Rajagopal walk (y up, tab-padded header) with its ground reactions: two right stances.
"$foot_cli" fit "$data/motion_capture_walk_ankles.trc" --forces "$data/grf_walk_every10th.mot" --marker R.Ankle --json > "$dir/walk.json"
python3 - "$dir/walk.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
stances = r["trials"][0]["stances"]
assert [s["rule"] for s in stances] == ["force ground_force_r_"] * 2 and all(s["fitted"] for s in stances), stances
assert r["trials"][0]["vertical_axis"] == "y", r["trials"][0]
p = {q["name"]: q for q in r["hmt"]["parameters"]}
ranges = {"h_F": (0.061, 0.116), "l_HA": (0.007, 0.154), "l_HM": (0.161, 0.379), "l_MT": (0.0, 0.126), "gamma_F": (0.52, 1.57)}
for name, (lo, hi) in ranges.items():
    assert lo <= p[name]["value"] <= hi, (name, p[name]["value"])
    assert p[name]["stride_spread"] is not None and p[name]["boundary_spread"] is not None, p[name]
PY

# A NaN in row 5 (line 9 of the .trc), column 4 (LMAL Y) is a missing sample, filled; text there
# is a malformed file.
awk 'NR == 9 { $4 = "nan" } { print }' OFS='\t' "$dir/trials/trial1.trc" > "$dir/gap.trc"
"$foot_cli" fit "$dir/gap.trc" --no-spread > "$dir/gap.txt"
grep -q "1 gap(s) of the ankle markers up to 50 ms interpolated" "$dir/gap.txt"
awk 'NR == 9 { $4 = "12x" } { print }' OFS='\t' "$dir/trials/trial1.trc" > "$dir/bad.trc"
set +e
"$foot_cli" fit "$dir/bad.trc" 2> "$dir/err.txt"
code=$?
set -e
test "$code" -eq 2
grep -q "bad.trc:9:4: LMAL Y: '12x' is not a number" "$dir/err.txt"
echo "foot_fit_cli: ok"
