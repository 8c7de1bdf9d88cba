"""cyclopt.Foot, evaluate_gait and optimise_gait against cyclopt's C++ libraries."""

import json
import math
import threading

import numpy as np
import pytest

import cyclopt
from reference import assert_same_gait, assert_same_trajectory, run


@pytest.mark.parametrize("foot, speed", [("point", 1.0), ("P1-barefoot-left-HM", 1.3)])
def test_evaluate_gait_is_the_cpp_evaluation_bit_for_bit(foot, speed):
    f = cyclopt.Foot.preset(foot)
    spec = {"scene": "walker", "task": "optimise", "foot": f.to_dict(), "speed": speed, "points": 200}
    expected = run("evaluate", json.dumps(spec))
    x = cyclopt.starting_gait(f, speed)
    assert [v.hex() for v in x] == [float(v).hex() for v in expected["x"]]
    gait = cyclopt.evaluate_gait(f, x, speed, points=200)
    assert gait.scalars["real"]
    assert_same_gait(gait.scalars, expected["gait"])
    np.testing.assert_array_equal(gait.scalars["bezier_coefficients [rad]"], expected["gait"]["bezier_coefficients"])
    assert_same_trajectory(gait.trajectories, expected["trajectory"])


def test_evaluate_gait_runs_threads_in_parallel_without_changing_results():
    foot = cyclopt.Foot.preset("point")
    x = cyclopt.starting_gait(foot, 1.0)
    alone = cyclopt.evaluate_gait(foot, x, 1.0).scalars["f_mech [-]"]
    found = []
    threads = [threading.Thread(target=lambda: found.append(cyclopt.evaluate_gait(foot, x, 1.0).scalars["f_mech [-]"]))
               for _ in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert [v.hex() for v in found] == [alone.hex()] * 4


def test_bad_walker_fields_raise_spec_errors_naming_the_field():
    foot = cyclopt.Foot.preset("point")
    x = cyclopt.starting_gait(foot, 1.0)
    with pytest.raises(cyclopt.SpecError) as e:
        cyclopt.evaluate_gait(foot, x, 1.0, points=5)
    assert e.value.field == "points" and "[25, 20000]" in e.value.message
    with pytest.raises(cyclopt.SpecError) as e:
        cyclopt.evaluate_gait(foot, x, 9.0)
    assert e.value.field == "speed"
    with pytest.raises(ValueError, match="x: 3 entries"):
        cyclopt.evaluate_gait(foot, x[:3], 1.0)


def test_foot_fields_are_checked_as_the_server_checks_them():
    fields = cyclopt.Foot.preset("P1-barefoot-left-HM").to_dict()
    assert cyclopt.Foot(**fields).to_dict() == fields
    with pytest.raises(cyclopt.SpecError) as e:
        cyclopt.Foot(**{**fields, "k_HM": -1.0})
    assert e.value.field == "foot.k_HM"
    with pytest.raises(cyclopt.SpecError) as e:
        cyclopt.Foot(**{**fields, "toes": 1})
    assert e.value.field.startswith("foot")
    with pytest.raises(cyclopt.SpecError) as e:
        cyclopt.Foot.preset("P9-sandals")
    assert e.value.field == "preset"
    assert "point" in cyclopt.Foot.preset_names()


def test_mass_properties_scale_with_density_and_need_one():
    foot = cyclopt.Foot.preset("P1-barefoot-left-HM")
    one, two = foot.mass_properties(density=10.0), foot.mass_properties(density=20.0)
    assert one["area [m^2]"] > 0 and one["area [m^2]"] == two["area [m^2]"]
    assert two["mass [kg]"] == pytest.approx(2 * one["mass [kg]"], rel=1e-14)
    assert one["com_x [m]"] == two["com_x [m]"]
    # The parallel-axis theorem (eq. E.6) between the two inertias.
    assert one["inertia_com [kg m^2]"] == pytest.approx(
        one["inertia_ankle [kg m^2]"] - one["mass [kg]"] * one["com_distance [m]"] ** 2, rel=1e-12)
    with pytest.raises(cyclopt.SpecError) as e:
        foot.mass_properties(density=-1.0)
    assert e.value.field == "density"


def test_rolling_function_derivatives_and_convexity():
    foot = cyclopt.Foot.preset("P1-barefoot-left-HM")
    theta = np.linspace(-0.5, 0.5, 101)
    r = foot.rolling(theta)
    h = 1e-6
    up, down = foot.rolling(theta + h), foot.rolling(theta - h)
    # F' and F'' against central differences of F and F' (eq. 3.10), the radius >= 0 (appendix A).
    np.testing.assert_allclose((up["F [m]"] - down["F [m]"]) / (2 * h), r["dF [m]"], atol=1e-7)
    np.testing.assert_allclose((up["dF [m]"] - down["dF [m]"]) / (2 * h), r["ddF [m]"], atol=1e-7)
    assert (r["curvature_radius [m]"] >= 0).all()
    assert not cyclopt.Foot.preset("point").rolling([0.1, 0.2])["F [m]"].any()


def test_optimise_gait_reaches_a_feasible_kkt_point():
    foot = cyclopt.Foot.preset("point")
    opt = cyclopt.optimise_gait(foot, 1.0, points=50)
    assert opt.converged, opt.values["solver"]
    assert opt.values["solver"]["termination"] in ("converged", "acceptable")
    assert abs(opt.scalars["speed_equality [m/s]"]) <= 1e-8
    assert opt.scalars["max_inequality [-]"] <= 1e-8
    # The optimum is a gait: evaluating its x gives the same gait.
    again = cyclopt.evaluate_gait(foot, opt.x, 1.0, points=50)
    assert again.scalars["f_mech [-]"] == opt.scalars["f_mech [-]"]
    assert math.isfinite(opt.scalars["f_mech [-]"]) and opt.trajectories["time [s]"].shape == (50,)
