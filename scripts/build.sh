#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
# Configures and builds meff into ${MEFF_BUILD_DIR:-build}. Extra arguments go to cmake.
# MEFF_BUILD_TARGET=NAME builds that target (and what it needs) instead of everything.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${MEFF_BUILD_DIR:-build}"
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo "$@" >/dev/null
cmake --build "$BUILD_DIR" -j"$(nproc)" ${MEFF_BUILD_TARGET:+--target "$MEFF_BUILD_TARGET"}
