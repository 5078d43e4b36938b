"""The foundation's verification cases at coarse size, with the tolerances they state."""
import pytest

from shockfem.verify import CASES, run_cases


@pytest.mark.parametrize("name", list(CASES))
def test_case_passes_at_coarse_size(name, tmp_path):
    checks = run_cases([name], "coarse", str(tmp_path), echo=lambda *a: None)
    failed = [c for c in checks if not c["passed"]]
    assert checks and not failed, failed
