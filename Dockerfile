# Batch studies in a container: docker build -t shockfem . && docker run --rm -v $PWD/results:/app/results shockfem run studies/foundation/bar_impact.toml
FROM debian:bookworm
ENV OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 DEBIAN_FRONTEND=noninteractive
WORKDIR /app
COPY . /app
# The same install script as `make` and CI, so CI exercises every step of this image.
# Without ParaView (INSTALL_PARAVIEW=0): the image runs scenes, studies and sweeps, not the test suite.
RUN INSTALL_PARAVIEW=0 bash scripts/install.sh && rm -rf /var/lib/apt/lists/*
ENTRYPOINT ["/app/.venv/bin/shockfem"]
CMD ["--help"]
