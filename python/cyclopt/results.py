"""Jobs and their results, from cycloptd over LCM (:class:`Client`) or from a database file opened
read-only (:func:`open_database`), through cyclopt's C++ client: the same receiver, wire checks and
message signatures as the ``cyclopt`` command (docs/service.md)."""

from __future__ import annotations

import json
import time
from typing import Any, Iterator, Optional

import numpy as np
import pandas as pd

from . import _results
from .errors import SpecError

NoAnswer = _results.NoAnswer  # cycloptd did not answer in time (a TimeoutError)
QueryError = _results.QueryError  # the server refused a query
SignatureRejected = _results.SignatureRejected  # the server does not accept this client's key


class Job:
    """One job. Its rows come from wherever it was found: the server or a database file."""

    def __init__(self, results: Any, job_id: int) -> None:
        self._results = results
        self.id = int(job_id)

    def status(self) -> dict[str, Any]:
        """The job's row: ``state`` (queued, running, done, failed, cancelled), ``points_stored``,
        ``progress_percent``, ``error``, times in Unix seconds, the ``spec``, ..."""
        return json.loads(self._results.rows("job", self.id))[0]

    def points(self) -> pd.DataFrame:
        """One row per stored point: ``curve``, ``point``, the curves' parameter (``speed [m/s]``),
        ``objective [-]``, ``iterations``, ``status``, and the gait's scalars (``f_mech [-]``,
        ``step_length [m]``, ``step_period [s]``, ``floquet_multiplier [-]``,
        ``impact_energy_loss [J]``, ..., NaN for points without a gait)."""
        return pd.DataFrame(self._results.point_columns(self.id))

    def curves(self) -> pd.DataFrame:
        """One row per solution curve: ``curve``, ``name``, ``parameter_name``, ``points``."""
        return pd.DataFrame(json.loads(self._results.rows("curves", self.id)),
                            columns=["curve", "name", "parameter_name", "points"])

    def events(self) -> pd.DataFrame:
        """The job's log: ``at [s]`` (Unix seconds), ``kind``, ``message``."""
        frame = pd.DataFrame(json.loads(self._results.rows("events", self.id)), columns=["at", "kind", "message"])
        return frame.rename(columns={"at": "at [s]"})

    def trajectory(self, point: Any) -> Optional[dict[str, np.ndarray]]:
        """The stored trajectory of a point (a row of :meth:`points`, or ``(curve, point)``) as
        NumPy arrays on the phase grid: ``"time [s]"``, ``"q [rad]"`` (rows theta, q_b),
        ``"torque [N m]"``, ...; None when the point has none."""
        curve, index = point if isinstance(point, (tuple, list)) else (point["curve"], point["point"])
        return self._results.trajectory(self.id, int(curve), int(index))

    def watch(self, timeout: float = 3600.0) -> Iterator[dict[str, Any]]:
        """Progress records as they arrive (``percent``, ``phase``, ``points_done``,
        ``best_objective``, ``eta [s]``, ...) until the job ends: the last record is the job's done
        record (``state``, ``points_stored``, ``run [s]``, ``error``). Raises :class:`NoAnswer`
        when the job has not ended within ``timeout`` seconds."""
        if self._results.reads_database:
            raise RuntimeError("a database opened read-only has no progress to watch; use Job.status()")
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            progress, done = self._results.watch(self.id, min(2.0, max(deadline - time.monotonic(), 0.01)))
            yield from progress
            if done is not None:
                yield done
                return
        raise NoAnswer(f"job {self.id} did not end within {timeout} s")

    def wait(self, timeout: float = 3600.0) -> dict[str, Any]:
        """Watches the job to its end and returns its done record."""
        record: dict[str, Any] = {}
        for record in self.watch(timeout):
            pass
        return record

    def cancel(self) -> dict[str, Any]:
        """Asks the server to cancel the job; returns its answer (``accepted``, ``state``)."""
        ack = self._results.cancel(self.id)
        if ack is None:
            raise NoAnswer(f"no answer to the cancellation of job {self.id}")
        return ack

    def __repr__(self) -> str:
        return f"Job({self.id})"


class _Results:
    def __init__(self, results: Any) -> None:
        self._results = results

    def job(self, job_id: int) -> Job:
        """The job ``job_id`` (raises :class:`QueryError` / ``ValueError`` when there is none)."""
        job = Job(self._results, job_id)
        job.status()
        return job

    def jobs(self, state: str = "") -> pd.DataFrame:
        """One row per job (optionally only those in ``state``)."""
        return pd.DataFrame(json.loads(self._results.rows("jobs", 0, state)))


class Database(_Results):
    """A results database opened read-only: the same :class:`Job` objects, without a server."""


class Client(_Results):
    """A client of cycloptd. ``lcm_url``: the server's LCM URL (default: ``$LCM_DEFAULT_URL``, else
    LCM's default); ``key_file``: sign requests and believe only messages signed with its first
    key (default: ``$CYCLOPT_KEY_FILE``, else unsigned); ``timeout``: seconds for each answer."""

    def __init__(self, lcm_url: str = "", key_file: str = "", timeout: float = 10.0) -> None:
        super().__init__(_results.Results("", lcm_url, key_file, timeout))

    def submit(self, spec: dict[str, Any], request_id: str = "") -> Job:
        """Queues a job spec (docs/walker-jobs.md; its schema: ``cyclopt schema``). A spec the server
        rejects raises :class:`cyclopt.SpecError` naming the field; no answer raises :class:`NoAnswer`."""
        ack = self._results.submit(json.dumps(spec), request_id)
        if ack is None:
            raise NoAnswer("no answer from cycloptd to the submission")
        if not ack["accepted"]:
            raise SpecError(ack["field"], ack["problem"])
        return Job(self._results, ack["job_id"])

    @property
    def malformed_received(self) -> int:
        """Received messages that were not a well-formed encoding of their channel's type (ignored)."""
        return self._results.malformed_received

    @property
    def unverified_received(self) -> int:
        """Well-formed messages dropped because they were not signed with this client's key."""
        return self._results.unverified_received


def open_database(path: str) -> Database:
    """A results database file (cycloptd's ``database``), read-only."""
    return Database(_results.Results(str(path), "", "", 10.0))
