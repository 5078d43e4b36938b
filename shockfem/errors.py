"""Errors a user can act on, and the exit codes the CLI gives them."""
from __future__ import annotations

EXIT_OK = 0
EXIT_BAD_INPUT = 2
EXIT_UNSTABLE = 3
EXIT_INTERRUPTED = 128          # + the signal's number (130 for SIGINT, 143 for SIGTERM), as shells report it


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


class RunInterrupted(Exception):
    """SIGINT or SIGTERM stopped the run between two steps; its outputs were finished and kept (status
    ``interrupted``, exit code 128 + the signal's number)."""

    def __init__(self, signum: int, time: float):
        self.signum = signum
        self.time = time
        super().__init__(f"interrupted by signal {signum} at t = {time:.6g} s")
