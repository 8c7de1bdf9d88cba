"""Two feet compared through cycloptd, notebook style (each "# %%" is a cell in Jupyter or VS Code).

One speed sweep per foot on the server (docs/walker-jobs.md), their optima per speed side by side
in a pandas table with the second foot's saving in f_mech (seed 001 eq. 5.102), and a figure: f_mech
and step length over speed, and the stance knee's torque over one step at a common speed.

    PYTHONPATH=build/python python3 examples/compare_two_feet.py --out compare_two_feet.png

The server is found as the ``cyclopt`` command finds it ($LCM_DEFAULT_URL, $CYCLOPT_KEY_FILE, or
--lcm-url / --key-file).
"""

# %% Options
import argparse

import matplotlib

matplotlib.use("Agg")  # figures go to a file
import matplotlib.pyplot as plt
import pandas as pd

import cyclopt

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--feet", default="P1-barefoot-left-HM-SG,P1-shoes-left-HM-SG", help="two foot presets (cyclopt.Foot.preset_names())")
parser.add_argument("--speeds", default="1.0:0.1:1.2", help="LO:STEP:HI in m/s")
parser.add_argument("--starts", type=int, default=2, help="multistart starts at the seed speed")
parser.add_argument("--out", default="compare_two_feet.png", help="the figure (PNG, SVG or PDF)")
parser.add_argument("--lcm-url", default="")
parser.add_argument("--key-file", default="")
args = parser.parse_args()
feet = args.feet.split(",")
lo = float(args.speeds.split(":")[0])

# %% Submit one sweep per foot and watch both to their end
client = cyclopt.Client(lcm_url=args.lcm_url, key_file=args.key_file)
jobs = {}
for foot in feet:
    jobs[foot] = client.submit({"scene": "walker", "task": "sweep", "name": f"compare_two_feet {foot}", "foot": foot,
                                "speeds": args.speeds, "multistart": {"starts": args.starts, "seed": 1, "scale": 0.02},
                                "continuation": {"seed_speeds": lo}})
for foot, job in jobs.items():
    done = job.wait(timeout=600)
    print(f"{foot}: job {job.id} {done['state']}, {done['points_stored']} points in {done['run [s]']:.1f} s")

# %% The optimum per speed (curve 0 of a sweep), side by side
columns = ["f_mech [-]", "step_length [m]", "step_period [s]", "floquet_multiplier [-]", "status"]
best = {foot: job.points().query("curve == 0").set_index("speed [m/s]") for foot, job in jobs.items()}
table = pd.concat({foot: frame[columns] for foot, frame in best.items()}, axis=1)
a, b = feet
table[("saving", f"{b} vs {a} [%]")] = 100 * (1 - table[(b, "f_mech [-]")] / table[(a, "f_mech [-]")])
with pd.option_context("display.width", 200, "display.max_columns", 20, "display.precision", 4):
    print(table)

# %% Figure: f_mech and step length over speed, knee torque over one step
fig, axes = plt.subplots(1, 3, figsize=(13, 4), constrained_layout=True)
for foot, frame in best.items():
    ok = frame[frame["status"] == "converged"]
    axes[0].plot(ok.index, ok["f_mech [-]"], "o-", label=foot)
    axes[1].plot(ok.index, ok["step_length [m]"], "o-", label=foot)
common = sorted(set.intersection(*(set(f[f["status"] == "converged"].index) for f in best.values())))
if common:
    speed = common[len(common) // 2]
    for foot, job in jobs.items():
        row = best[foot].loc[speed]
        trajectory = job.trajectory((int(row["curve"]), int(row["point"])))
        if trajectory is not None:  # torque rows: hips H1, H2, knees K1, K2 (, ankles)
            axes[2].plot(trajectory["time [s]"], trajectory["torque [N m]"][2], label=foot)
    axes[2].set_title(f"stance knee torque at {speed:g} m/s")
axes[0].set(xlabel="speed [m/s]", ylabel="f_mech [-]", title="mechanical cost of transport (5.102)")
axes[1].set(xlabel="speed [m/s]", ylabel="step length [m]", title="step length")
axes[2].set(xlabel="time since impact [s]", ylabel="torque [N m]")
for ax in axes:
    ax.grid(True, alpha=0.3)
    ax.legend()
fig.savefig(args.out, dpi=120)
print(f"figure: {args.out}")
