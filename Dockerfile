# Batch studies in a container:
#   docker build -t shockfem .
#   docker run --rm --user "$(id -u):$(id -g)" -v "$PWD/results:/app/results" shockfem run studies/foundation/bar_impact.toml
# (--user: the results belong to you, not to root; README, "In a container")
FROM debian:bookworm
ENV OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 DEBIAN_FRONTEND=noninteractive
WORKDIR /app
# The same install script as `make` and CI, in three layers from the slowest to change to the quickest, so
# that an edit of the source re-runs only the last: Debian's packages (the script alone), then the venv and
# PyPI's packages (pyproject.toml and a placeholder package), then the source.
# Without ParaView (INSTALL_PARAVIEW=0): the image runs scenes, studies and sweeps, not the test suite.
COPY scripts/install.sh scripts/install.sh
RUN INSTALL_PARAVIEW=0 INSTALL_STEPS=debian bash scripts/install.sh && rm -rf /var/lib/apt/lists/*
COPY pyproject.toml constraints.txt README.md ./
RUN mkdir -p shockfem && touch shockfem/__init__.py && INSTALL_PARAVIEW=0 bash scripts/install.sh
COPY . /app
RUN INSTALL_PARAVIEW=0 bash scripts/install.sh \
 && mkdir -p /app/home /app/results
# Any user id (docker run --user) writes numba's caches beside the package's sources, the meshes' in
# meshes/, and FFCx's and matplotlib's under HOME (a user id the image does not know gets HOME=/, which it
# cannot write); the venv stays root's and read-only (a chmod of it would copy its 3 GB into a new layer).
# HOME is set before the warm step, so that the FFCx forms it compiles land where a run looks for them.
ENV HOME=/app/home
# numba's kernels and FFCx's forms compiled into the image (`shockfem warm`, a few steps of the studies'
# scenes), so that a `docker run --rm` computes at once instead of compiling for a minute or more. Kept for
# the CPU model that builds the image: on another one, numba compiles them again at the first run.
RUN SHOCKFEM_PICTURES=0 /app/.venv/bin/shockfem warm \
 && chmod -R a+rwX /app/shockfem /app/meshes /app/home /app/results
ENTRYPOINT ["/app/.venv/bin/shockfem"]
CMD ["--help"]
