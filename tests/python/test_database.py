"""A sweep stored through the store API, read back with cyclopt.open_database as DataFrames."""

import io

import numpy as np
import pandas as pd

import cyclopt
from reference import assert_same_trajectory, base_name, run


def test_stored_sweep_round_trips_through_a_dataframe(tmp_path):
    db = tmp_path / "results.db"
    stored = run("store", str(db), "40", "7")
    database = cyclopt.open_database(str(db))
    job = database.job(stored["job_id"])
    assert job.status()["state"] == "done"
    points = job.points()
    assert len(points) == 40
    assert list(points["point"]) == [p["point"] for p in stored["points"]]
    np.testing.assert_array_equal(points["speed [m/s]"], [p["parameter"] for p in stored["points"]])
    gait_columns = [c for c in points.columns if c.endswith("]") and base_name(c) in stored["points"][0]["gait"]]
    assert {"f_mech [-]", "step_length [m]", "step_period [s]", "floquet_multiplier [-]"} <= set(gait_columns)
    for column in gait_columns:
        expected = [p["gait"].get(base_name(column), np.nan) for p in stored["points"]]
        np.testing.assert_array_equal(points[column].to_numpy(), np.asarray(expected, dtype=float), err_msg=column)
    assert list(points["real"]) == [p["gait"]["real"] for p in stored["points"]]
    # CSV and back keeps every bit.
    again = pd.read_csv(io.StringIO(points.to_csv(index=False)), float_precision="round_trip")
    pd.testing.assert_frame_equal(again, points, check_exact=True)
    # Trajectories: the first three points have one.
    assert_same_trajectory(job.trajectory(points.iloc[0]), stored["points"][0]["trajectory"])
    assert job.trajectory((0, 5)) is None
    curves = job.curves()
    assert list(curves["parameter_name"]) == ["speed"] and list(curves["points"]) == [40]
    assert list(database.jobs()["id"]) == [stored["job_id"]]
