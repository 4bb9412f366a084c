#!/usr/bin/env bash
# Idempotent set-up for a fresh Debian 12 machine: install missing system
# packages, configure build/ once, then (re)build incrementally.
# Env: COSMO_BUILD_DIR (default <repo>/build; relative paths are taken from
# the repository root), COSMO_JOBS (default 2).
set -euo pipefail

REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${COSMO_BUILD_DIR:-build}"
[[ "$BUILD" = /* ]] || BUILD="$REPO/$BUILD"
JOBS="${COSMO_JOBS:-2}"

log() { echo "[cosmo] $*"; }

# libopenblas0-pthread: MUMPS on Debian's reference BLAS factorizes ~2.5x
# slower (measured, benchmarks/README.md); OpenBLAS takes over libblas.so.3.
PACKAGES=(libdeal.ii-dev numdiff gmsh python3-matplotlib python3-numpy python3-scipy python3-sympy python3-h5py paraview python3-paraview xvfb xauth cmake g++ make ccache libopenblas0-pthread libmetis-dev openmpi-bin)

missing=()
for pkg in "${PACKAGES[@]}"; do
  # dpkg-query fails for unknown packages; treat that as "not installed".
  status="$(dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null || true)"
  [[ "$status" == "install ok installed" ]] || missing+=("$pkg")
done

if ((${#missing[@]})); then
  log "installing missing packages: ${missing[*]}"
  SUDO=()
  if [[ "$(id -u)" -ne 0 ]]; then
    command -v sudo >/dev/null || { log "not root and no sudo; install: ${missing[*]}" >&2; exit 1; }
    # -n: fail instead of prompting, since CI has no stdin.
    SUDO=(sudo -n)
  fi
  # env passes DEBIAN_FRONTEND through sudo, which would otherwise drop it.
  "${SUDO[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update </dev/null
  "${SUDO[@]}" env DEBIAN_FRONTEND=noninteractive \
    apt-get install -y --no-install-recommends "${missing[@]}" </dev/null
else
  log "all system packages present"
fi

if [[ ! -f "$BUILD/CMakeCache.txt" ]]; then
  log "configuring $BUILD"
  cmake_args=(-S "$REPO" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release)
  command -v ccache >/dev/null && cmake_args+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  cmake "${cmake_args[@]}"
else
  log "reusing configured $BUILD"
fi

log "building with $JOBS jobs"
cmake --build "$BUILD" -j"$JOBS"
log "build done: $BUILD"
