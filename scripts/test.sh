#!/usr/bin/env bash
# Builds meff and runs the whole test suite through CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh "$@"
ctest --test-dir "${MEFF_BUILD_DIR:-build}" --output-on-failure -j"$(nproc)"
