#!/bin/bash
# cyclopt-foot synth / fit end to end (issue 20 items 3-5): synthetic trials of a preset are
# written as .trc and CSV, fitted (figures, saved foot usable by cyclopt-foot --foot), and a
# malformed file is rejected with exit code 2 and FILE:LINE:COLUMN.
set -euo pipefail
foot_cli=$1
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
assert all(t["rolling_phase"] == "force column Fz" for t in r["trials"]), r["trials"]
assert r["hmt"]["rms"] <= r["hm"]["rms"], (r["hmt"]["rms"], r["hm"]["rms"])
PY
for f in fit_hm_ankle fit_hm_outline fit_hmt_ankle fit_hmt_outline; do
  test -s "$dir/plots/$f.png" && test -s "$dir/plots/$f.svg"
done
"$foot_cli" --foot "$dir/foot.json" > /dev/null

# The .trc trials (rolling phase from the kinematics: .trc has no force column).
"$foot_cli" fit "$dir"/trials/trial{1,2,3}.trc --model HMT --no-toe-bound > "$dir/fit_trc.txt"
grep -q "converged" "$dir/fit_trc.txt"
grep -q "kinematics" "$dir/fit_trc.txt"

# The same trials as the inline ankle tracks of a foot_fit job spec (service/foot_fit_kind.hpp).
"$foot_cli" fit "$dir"/trials/trial{1,2,3}.csv --job-spec "$dir/job.json" 2> /dev/null
python3 - "$dir/job.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
assert s["task"] == "foot_fit" and len(s["trials"]) == 3, s.keys()
assert all(len(t["x"]) == len(t["z"]) >= 10 for t in s["trials"])
PY

# A NaN in row 5 (line 9 of the .trc), column 4 (LMAL Y).
awk 'NR == 9 { $4 = "nan" } { print }' OFS='\t' "$dir/trials/trial1.trc" > "$dir/bad.trc"
set +e
"$foot_cli" fit "$dir/bad.trc" 2> "$dir/err.txt"
code=$?
set -e
test "$code" -eq 2
grep -q "bad.trc:9:4: LMAL Y: 'nan' is not finite" "$dir/err.txt"
echo "foot_fit_cli: ok"
