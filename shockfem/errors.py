"""Errors a user can act on, and the exit codes the CLI gives them."""
from __future__ import annotations

EXIT_OK = 0
EXIT_BAD_INPUT = 2
EXIT_UNSTABLE = 3


class ModelError(Exception):
    """A scene that passed validation but cannot be modelled as written (exit code 2)."""


class UnstableRun(Exception):
    """The run went unstable; ``diagnosis`` names the body, element and time (exit code 3)."""

    def __init__(self, diagnosis: str, time: float, body: str | None = None, element: int | None = None):
        self.diagnosis = diagnosis
        self.time = time
        self.body = body
        self.element = element
        super().__init__(diagnosis)
