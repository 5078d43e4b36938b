"""``dolfinx_start.import_dolfinx``: dolfinx comes in without setuptools' ``pkg_resources`` (0.1 s of a run's
start), ufl and ffcx report the versions their installed metadata gives, and ``pkg_resources`` imports
normally afterwards, also through the stand-in ufl and ffcx keep.  In a fresh interpreter: this test
process has dolfinx (and maybe pkg_resources) already."""
import subprocess
import sys


def test_dolfinx_comes_in_without_pkg_resources_which_stays_loadable():
    code = (
        "import sys, importlib.metadata\n"
        "import shockfem.cli\n"
        "import dolfinx, ufl, ffcx\n"
        "print('pkg_resources' in sys.modules)\n"
        "print(ufl.__version__ == importlib.metadata.version('fenics-ufl'),\n"
        "      ffcx.__version__ == importlib.metadata.version('fenics-ffcx'))\n"
        "import pkg_resources\n"
        "print(hasattr(pkg_resources, 'working_set'), type(pkg_resources).__name__)\n"
        "print(ufl.pkg_resources.working_set is pkg_resources.working_set)\n"
        "print(ufl.pkg_resources.get_distribution('fenics-ufl').version == ufl.__version__)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout.split()
    assert out == ["False", "True", "True", "True", "module", "True", "True"], out


def test_a_distribution_the_metadata_does_not_know_is_answered_by_pkg_resources():
    """The stand-in's fallback: the real ``pkg_resources`` raises its own error for an unknown name."""
    code = (
        "import sys\n"
        "from shockfem import dolfinx_start\n"
        "lookup = dolfinx_start._VersionLookup('pkg_resources')\n"
        "sys.modules['pkg_resources'] = lookup\n"
        "try:\n"
        "    lookup.get_distribution('no-such-distribution-shockfem')\n"
        "except Exception as e:\n"
        "    print(type(e).__name__)\n"
        "print(type(sys.modules['pkg_resources']).__name__)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout.split()
    assert out == ["DistributionNotFound", "module"], out
