#!/usr/bin/env bash
# Build the Dockerfile and run its documented command without a Docker engine or Docker Hub:
# buildah (chroot isolation, vfs storage) on a Debian bookworm base made by debootstrap from the
# Debian mirror.  Behind a TLS-intercepting proxy the host's extra CA certificates and pip.conf
# are copied into the base, as a site's own base image would carry them.  As root, Debian 12.
set -euo pipefail
cd "$(dirname "$0")/.."
WORK=${WORK:-/tmp/shockfem-container}
S="--storage-driver vfs"
apt-get install -y -q --no-install-recommends buildah debootstrap >/dev/null
mkdir -p "$WORK"
if [ ! -d "$WORK/rootfs/etc" ]; then
  debootstrap --variant=minbase bookworm "$WORK/rootfs" http://deb.debian.org/debian
fi
if ls /usr/local/share/ca-certificates/*.crt >/dev/null 2>&1; then
  mkdir -p "$WORK/rootfs/usr/local/share/ca-certificates" "$WORK/rootfs/etc/ssl/certs"
  cp /usr/local/share/ca-certificates/*.crt "$WORK/rootfs/usr/local/share/ca-certificates/"
  cp /etc/ssl/certs/ca-certificates.crt "$WORK/rootfs/etc/ssl/certs/"
fi
[ -f /etc/pip.conf ] && cp /etc/pip.conf "$WORK/rootfs/etc/pip.conf"
if ! buildah $S images -q localhost/debian:bookworm >/dev/null 2>&1; then
  base=$(buildah $S from scratch)
  cp -a "$WORK/rootfs/." "$(buildah $S mount "$base")/"
  buildah $S umount "$base" >/dev/null
  buildah $S commit -q "$base" localhost/debian:bookworm >/dev/null
  buildah $S rm "$base" >/dev/null
fi
rm -rf "$WORK/context" && git clone -q . "$WORK/context"
(cd "$WORK/context" && buildah $S bud --isolation chroot --pull=never -t localhost/shockfem -f Dockerfile .)
mkdir -p "$WORK/results"
ctr=$(buildah $S from --pull=never localhost/shockfem)
buildah $S run --isolation chroot -v "$WORK/results:/app/results" "$ctr" -- \
  /app/.venv/bin/shockfem run studies/foundation/bar_impact.toml
buildah $S run --isolation chroot "$ctr" -- /app/.venv/bin/shockfem verify free_flight rod_on_wall slotted_ring
# a whole study into the mounted directory
buildah $S run --isolation chroot -v "$WORK/results:/app/results" "$ctr" -- \
  /app/.venv/bin/shockfem study amplifier --size smoke --out results/amplifier
# a sweep (both cores, then Dask's LocalCluster) into the mounted directory
buildah $S run --isolation chroot -v "$WORK/results:/app/results" "$ctr" -- \
  /app/.venv/bin/shockfem sweep studies/foundation/bar_impact.toml --vary "boundary.0.value=[2, 5] m/s" \
  --set 'scene.end_time="40 us"' --out results/sweep_local --no-progress
buildah $S run --isolation chroot -v "$WORK/results:/app/results" "$ctr" -- \
  /app/.venv/bin/shockfem sweep studies/foundation/bar_impact.toml --vary "boundary.0.value=[2, 5] m/s" \
  --set 'scene.end_time="40 us"' --out results/sweep_dask --executor dask --no-progress
cat "$WORK/results/sweep_local/cases.csv"
buildah $S rm "$ctr" >/dev/null
ls "$WORK/results/bar_impact" "$WORK/results/amplifier"
