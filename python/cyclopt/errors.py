"""Errors of the cyclopt package."""


class SpecError(ValueError):
    """Invalid input, from Python or from the server's validation of a job spec.

    ``field`` is the input's path (``"speed"``, ``"foot.k_HM"``, ``"multistart.starts"``),
    ``message`` the admissible range or the reason; ``str(error)`` is ``"<field>: <message>"``.
    """

    def __init__(self, field: str, message: str) -> None:
        super().__init__(f"{field}: {message}")
        self.field = field
        self.message = message
