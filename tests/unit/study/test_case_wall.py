"""A study's case read back from an earlier run (``--resume``) gives its run's wall time, not the read's."""
from shockfem.study.cases import run_wall


def test_a_case_read_back_reports_its_runs_wall_time():
    summary = {"wall_time_s": 118.4}
    assert run_wall(summary, 0.02, read_back=True) == 118.4
    assert run_wall(summary, 120.5, read_back=False) == 120.5       # run now: what running it took
    assert run_wall({}, 0.02, read_back=True) == 0.02                # no record of the run: the read's
