"""The Python package's overhead (issue 58, acceptance 2), printed for bench/results/python.txt:

1. cyclopt.evaluate_gait from Python (its scene cached, as repeated calls find it) against the C++
   call GaitEvaluator::evaluate with trajectories at P = 200, and against that call with the records
   the package converts (cyclopt-python-reference), on the point foot and an HM foot. Rounds
   alternate between Python and C++, each round a fresh process on either side (a process's
   memory layout alone moves a 0.1 ms call by up to 20 %), and the fastest round of each counts.
2. Job.points() of a 10,000-point job stored through the store API, read from the database file.

    PYTHONPATH=build/python CYCLOPT_PYTHON_REFERENCE=build/tests/python/cyclopt-python-reference \
        /usr/bin/python3 bench/python_overhead.py
"""

import json
import os
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tests", "python"))

import cyclopt  # noqa: E402
from reference import run  # noqa: E402

REPEATS, ROUNDS, POINTS = 300, 15, 10_000


def machine() -> str:
    lscpu = subprocess.run(["lscpu"], capture_output=True, text=True).stdout
    model = next((line.split(":", 1)[1].strip() for line in lscpu.splitlines() if line.startswith("Model name")), "?")
    with open("/proc/loadavg") as f:
        load = f.read().split()[:3]
    return f"CPU: {model}, {os.cpu_count()} cores; load average {' '.join(load)}"


def evaluate_overhead(foot_name: str, speed: float) -> None:
    foot = cyclopt.Foot.preset(foot_name)
    spec = {"scene": "walker", "task": "optimise", "foot": foot.to_dict(), "speed": speed, "points": 200}
    python, cpp, evaluate = [], [], []
    for _ in range(ROUNDS):
        reference = run("evaluate", json.dumps(spec), str(REPEATS))
        cpp.append(reference["call_seconds"])
        evaluate.append(reference["evaluate_seconds"])
        round_in_python = [sys.executable, __file__, "--python-round", foot_name, str(speed)]
        python.append(float(subprocess.run(round_in_python, capture_output=True, text=True, check=True).stdout))
    p, c, e = min(python), min(cpp), min(evaluate)
    print(f"evaluate_gait {foot_name} at {speed} m/s, P = 200: Python {1e3 * p:.3f} ms; C++ evaluate {1e3 * e:.3f} ms, "
          f"ratio {p / e:.3f}; C++ evaluate and records {1e3 * c:.3f} ms, ratio {p / c:.3f} "
          f"(best of {ROUNDS} rounds of {REPEATS})")


def python_round(foot_name: str, speed: float) -> float:
    """Mean seconds of one cyclopt.evaluate_gait over REPEATS calls, its scene cached."""
    foot = cyclopt.Foot.preset(foot_name)
    x = cyclopt.starting_gait(foot, speed, points=200)
    cyclopt.evaluate_gait(foot, x, speed, points=200)
    start = time.perf_counter()
    for _ in range(REPEATS):
        cyclopt.evaluate_gait(foot, x, speed, points=200)
    return (time.perf_counter() - start) / REPEATS


def points_time() -> None:
    with tempfile.TemporaryDirectory() as tmp:
        db = os.path.join(tmp, "results.db")
        start = time.perf_counter()
        job_id = run("store", db, str(POINTS), "11")["job_id"]
        stored = time.perf_counter() - start
        job = cyclopt.open_database(db).job(job_id)
        times = []
        for _ in range(3):
            start = time.perf_counter()
            frame = job.points()
            times.append(time.perf_counter() - start)
        size = os.path.getsize(db) / 1e6
        print(f"Job.points() of a {len(frame)}-point job ({len(frame.columns)} columns, database {size:.1f} MB, "
              f"filled in {stored:.1f} s): {min(times):.3f} s (runs: {', '.join(f'{t:.3f}' for t in times)})")


if __name__ == "__main__":
    if sys.argv[1:2] == ["--python-round"]:
        print(python_round(sys.argv[2], float(sys.argv[3])))
        sys.exit(0)
    print(machine())
    evaluate_overhead("point", 1.0)
    evaluate_overhead("P1-barefoot-left-HM", 1.3)
    points_time()
    print(machine())
