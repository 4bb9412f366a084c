#!/usr/bin/env bash
# Build, then run the ctest suite. Extra arguments go to ctest (e.g. -R rotation).
set -euo pipefail

REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${COSMO_BUILD_DIR:-build}"
[[ "$BUILD" = /* ]] || BUILD="$REPO/$BUILD"

bash "$REPO/scripts/setup.sh"
echo "[cosmo] running tests"
exec ctest --test-dir "$BUILD" --output-on-failure -j"${COSMO_JOBS:-2}" "$@"
