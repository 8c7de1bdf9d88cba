"""What cyclopt-python-reference (gait_reference.cpp) computes in C++, for the tests to compare."""

import json
import math
import os
import subprocess

import numpy as np

REFERENCE = os.environ.get("CYCLOPT_PYTHON_REFERENCE", "cyclopt-python-reference")


def run(*args: str) -> dict:
    return json.loads(subprocess.run([REFERENCE, *args], check=True, capture_output=True, text=True).stdout)


def base_name(key: str) -> str:
    """"f_mech [-]" -> "f_mech"."""
    return key.split(" [")[0]


def assert_same_gait(scalars: dict, record: dict) -> None:
    """Every scalar of a GaitRecord (JSON: exact decimals; absent or null where NaN) equals the
    Python value bit for bit."""
    compared = 0
    for key, value in scalars.items():
        name = base_name(key)
        if isinstance(value, float):
            expected = record.get(name)
            expected = math.nan if expected is None else expected
            assert (math.isnan(value) and math.isnan(expected)) or value.hex() == float(expected).hex(), key
            compared += 1
        elif isinstance(value, bool):
            assert value == record.get(name, False), key
    assert compared >= 10


def assert_same_trajectory(arrays: dict, record: dict) -> None:
    assert {base_name(k) for k in arrays} == {k for k, v in record.items() if len(v) > 0}
    for key, value in arrays.items():
        np.testing.assert_array_equal(value, np.asarray(record[base_name(key)], dtype=float), err_msg=key)
