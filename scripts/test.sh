#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
# Builds meff and runs the whole test suite through CTest. With --fast: builds only the engine
# and its unit tests (meff_unit_tests: the compiler and Catch2) and runs the unit tier alone
# (`ctest -L unit`, under a minute). Other arguments go to cmake.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" = "--fast" ]; then
    shift
    BUILD_DIR="${MEFF_BUILD_DIR:-build}"
    cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo "$@" >/dev/null
    cmake --build "$BUILD_DIR" -j"$(nproc)" --target meff_unit_tests
    ctest --test-dir "$BUILD_DIR" -L unit --output-on-failure -j"$(nproc)"
    exit
fi
scripts/build.sh "$@"
ctest --test-dir "${MEFF_BUILD_DIR:-build}" --output-on-failure -j"$(nproc)"
