"""cyclopt.Client against a live cycloptd (started by in_netns.sh, which signs with the key in
$CYCLOPT_KEY_FILE, inside a private network namespace)."""

import os
import subprocess
import time

import numpy as np
import pytest

import cyclopt
from reference import REFERENCE

SWEEP = {"scene": "walker", "task": "sweep", "foot": "point", "speeds": "0.9:0.1:1.1",
         "multistart": {"starts": 2, "seed": 3, "scale": 0.02}, "continuation": {"seed_speeds": 1.0}}
SLOW = {"scene": "walker", "task": "foot_sweep", "foot": "P2-shoes-left-HMT", "point_delay_ms": 200,
        "sweep": {"parameter": "density", "values": "1:1:200"}}


@pytest.fixture(scope="module")
def client():
    assert os.environ.get("CYCLOPT_KEY_FILE"), "run by in_netns.sh"
    c = cyclopt.Client()
    deadline = time.monotonic() + 20
    while True:  # the server is starting
        try:
            c.jobs()
            return c
        except cyclopt.NoAnswer:
            if time.monotonic() > deadline:
                raise


def test_submit_watch_points(client):
    job = client.submit(SWEEP)
    records = list(job.watch(timeout=100))
    done = records[-1]
    assert done["state"] == "done", done
    assert any("percent" in r for r in records[:-1])
    points = job.points()
    best = points[points["curve"] == 0]
    np.testing.assert_allclose(sorted(best["speed [m/s]"]), [0.9, 1.0, 1.1], rtol=1e-12)
    converged = best[best["status"] == "converged"]
    assert len(converged) >= 1 and (converged["f_mech [-]"] > 0).all()
    assert (abs(converged["mean_speed [m/s]"] - converged["speed [m/s]"]) < 1e-6).all()
    row = converged.iloc[0]
    trajectory = job.trajectory(row)
    assert trajectory is not None and trajectory["q [rad]"].shape[1] == trajectory["time [s]"].shape[0]
    assert job.status()["state"] == "done"
    assert list(job.curves()["curve"])[0] == 0
    # The same job from the database file, without the server.
    again = cyclopt.open_database(os.environ["CYCLOPT_DATABASE"]).job(job.id).points()
    assert again.drop(columns=["solved_at [s]"]).equals(points.drop(columns=["solved_at [s]"]))


def test_bad_spec_raises_naming_the_field(client):
    with pytest.raises(cyclopt.SpecError) as e:
        client.submit({**SWEEP, "points": 5})
    assert e.value.field == "points"
    with pytest.raises(cyclopt.SpecError) as e:
        client.submit({**SWEEP, "multistart": {"starts": 0}})
    assert e.value.field == "multistart.starts"


def test_forged_done_is_ignored_and_cancel_ends_the_job(client):
    job = client.submit(SLOW)
    before = client.unverified_received
    forger = subprocess.Popen([REFERENCE, "forge-done", str(job.id), "25"])
    records = []
    with pytest.raises(cyclopt.NoAnswer):
        for record in job.watch(timeout=3.0):
            records.append(record)
    forger.wait(timeout=10)
    assert not any("state" in r for r in records), "a forged done record ended the watch"
    assert client.unverified_received > before
    assert job.cancel()["accepted"]
    done = job.wait(timeout=30)
    assert done["state"] == "cancelled"
    assert job.status()["state"] == "cancelled"
