#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
# Installs everything meff needs from Debian 12's packages. Needs root (or sudo).
set -euo pipefail
SUDO=""
if [ "$(id -u)" != 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
# doxygen: the API reference (`docs` target, checked by the docs.reference test).
# libglfw3-dev and libimgui-dev: the `meff view` window (skipped when missing); xvfb, xauth and
# libgl1-mesa-dri (Mesa's llvmpipe, OpenGL 3.3+ without a GPU): its scripted test under Xvfb;
# ffmpeg: `meff render --gif/--mp4` and their frame-rate test; librsvg2-bin (rsvg-convert): the
# test that draws an SVG frame and compares it with the PNG.
# clang-14 and libclang-rt-14-dev (libFuzzer and clang's sanitizer runtimes; only recommended
# by clang-14, so named here): the scene loader's fuzz target, fuzz/, which .ci/run runs.
# zlib1g-dev: the gzip files of `meff validate --baseline` (meff::validation only).
# chromium: the browser check of `meff validate --report`'s page (tests/cli/check_report.py).
$SUDO apt-get install -y -qq --no-install-recommends \
    g++ cmake make pkg-config \
    catch2 libbox2d-dev libosmesa6-dev libpng-dev nlohmann-json3-dev libcli11-dev zlib1g-dev \
    libfreetype-dev fonts-dejavu-core \
    libglfw3-dev libimgui-dev libgl1-mesa-dri xvfb xauth ffmpeg librsvg2-bin \
    libbenchmark-dev python3 python3-matplotlib \
    doxygen \
    clang-14 libclang-rt-14-dev chromium >/dev/null
