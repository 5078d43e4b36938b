"""A Dask sweep keeps Dask's own log to itself: ``distributed`` says 65 INFO lines on a two-worker local
cluster that runs one task (measured with ``verbose=True``: workers starting, their addresses, stopping),
none of which a user can act on; ``shockfem sweep --verbose`` shows them, quiet is the default."""
import subprocess
import sys

import pytest

CLIENT = """
from shockfem.study.batch import _dask_client
with _dask_client(2, None, {verbose}) as client:
    assert client.submit(sum, [1, 2]).result() == 3
    client.cluster.close()
"""


@pytest.mark.parametrize("verbose", [False, True])
def test_dask_says_info_only_when_asked(verbose):
    out = subprocess.run([sys.executable, "-c", CLIENT.format(verbose=verbose)], capture_output=True, text=True,
                         timeout=300)
    assert out.returncode == 0, out.stderr
    info = [line for line in (out.stdout + out.stderr).splitlines() if "INFO" in line]
    assert (len(info) > 0) == verbose, info[:5]
