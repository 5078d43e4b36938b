#!/usr/bin/env bash
# Install everything shockfem needs on Debian 12 (bookworm), as root, from nothing.
# Idempotent: a second run installs nothing. Used by the Makefile, CI and the Dockerfile.
# ParaView (pvpython) and xvfb: the test that opens a run's fields with ParaView's own reader
# (INSTALL_PARAVIEW=0 leaves them out: the Dockerfile's batch image does not run the tests).
set -euo pipefail
cd "$(dirname "$0")/.."
VENV=${VENV:-.venv}
APT_PACKAGES="python3-dolfinx python3-petsc4py python3-slepc4py python3-mpi4py python3-h5py
  python3-numba python3-scipy python3-venv python3-pip python3-meshio python3-gmsh
  openmpi-bin libglu1-mesa libxrender1 libxcursor1 libxft2 libxinerama1 git make
  libegl1 libegl-mesa0 libgl1-mesa-dri"
# (the last three: pyvista's VTK draws the runs' pictures off screen through EGL and Mesa's software
# renderer; without them VTK finds no EGL, no OSMesa and no display, and crashes on its first render)
if [ "${INSTALL_PARAVIEW:-1}" = 1 ]; then
  APT_PACKAGES="$APT_PACKAGES paraview python3-paraview python3-matplotlib xvfb xauth x11-utils"
fi
missing=""
for p in $APT_PACKAGES; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
  echo "install: apt-get install$missing"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -q --no-install-recommends $missing
fi
# INSTALL_STEPS=debian: Debian's packages only (the Dockerfile's first layer, which a source edit keeps)
[ "${INSTALL_STEPS:-all}" = debian ] && exit 0
if [ ! -x "$VENV/bin/python" ]; then
  echo "install: venv $VENV (with Debian's dolfinx through --system-site-packages)"
  /usr/bin/python3 -m venv --system-site-packages "$VENV"
fi
if ! "$VENV/bin/python" -c "import shockfem, gmsh, pint, pytest, xdist, tqdm, distributed, pyDOE3, tomli_w, pyyeti, dask_jobqueue" 2>/dev/null \
   || [ pyproject.toml -nt "$VENV/.installed" ] || [ constraints.txt -nt "$VENV/.installed" ]; then
  echo "install: pip install -e .[test,viz,batch]"
  "$VENV/bin/pip" install -q --disable-pip-version-check -c constraints.txt -e ".[test,viz,batch]"
fi
# One matplotlib: Debian's (ParaView depends on it). A second copy in the venv would not be whole:
# Debian's mpl_toolkits is a regular package and wins over the venv's namespace one ("Unable to
# import Axes3D" on every import of pyplot).
if [ -d "$VENV/lib/python3.11/site-packages/matplotlib" ] \
   && dpkg-query -W -f='${Status}' python3-matplotlib 2>/dev/null | grep -q "install ok installed"; then
  echo "install: the venv's own matplotlib removed (Debian's python3-matplotlib serves)"
  "$VENV/bin/pip" uninstall -q -y matplotlib
fi
# One h5py: Debian's (python3-h5py, on Debian's HDF5 as dolfinx is). pip does not know Debian's by that
# name (its metadata says h5py.-debian-h5py-serial), so a package that asks for h5py (pyyeti, the SRS test's
# oracle) brings PyPI's wheel with an HDF5 of its own into the venv, in front of Debian's.
if [ -d "$VENV/lib/python3.11/site-packages/h5py" ] \
   && dpkg-query -W -f='${Status}' python3-h5py 2>/dev/null | grep -q "install ok installed"; then
  echo "install: the venv's own h5py removed (Debian's python3-h5py serves)"
  "$VENV/bin/pip" uninstall -q -y h5py
fi
"$VENV/bin/python" - <<'PY'
import warnings
warnings.simplefilter("error")
import dolfinx, numpy, gmsh
import matplotlib.pyplot  # no warning: one matplotlib
assert numpy.__version__.startswith("1.24"), f"numpy {numpy.__version__}: Debian's dolfinx needs 1.24"
print(f"install: ok (dolfinx {dolfinx.__version__}, gmsh {gmsh.__version__}, numpy {numpy.__version__})")
PY
touch "$VENV/.installed"
