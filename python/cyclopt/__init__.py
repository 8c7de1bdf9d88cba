"""cyclopt from Python: jobs on cycloptd, their stored results, and the walker's feet and gaits
computed by cyclopt's C++ libraries (docs/python.md). Units are SI and named in every column and
key, e.g. ``speed [m/s]``, ``f_mech [-]``."""

from .errors import SpecError
from .model import Foot, Gait, GaitOptimum, evaluate_gait, optimise_gait, starting_gait
from .results import Client, Database, Job, NoAnswer, QueryError, SignatureRejected, open_database

__all__ = [
    "Client", "Database", "Foot", "Gait", "GaitOptimum", "Job", "NoAnswer", "QueryError", "SignatureRejected",
    "SpecError", "evaluate_gait", "open_database", "optimise_gait", "starting_gait",
]
