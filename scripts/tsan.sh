#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
# Builds the test suite with ThreadSanitizer (-DMEFF_SANITIZE_THREAD=ON) into
# ${MEFF_BUILD_DIR:-build-tsan} and runs the thread tests under it: every test case tagged
# [threads] (tests/test_threads.cpp, and the thread-pool cases of tests/test_world_lifecycle.cpp,
# tagged [world][threads]). Exits nonzero on any ThreadSanitizer report. Extra arguments go to
# cmake. Not part of CI (.ci/run): TSan's runtime depends on the kernel's address-space layout,
# and CI's kernel is not known.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${MEFF_BUILD_DIR:-build-tsan}"
# Only the two test programs that hold [threads] cases are built, so the parts they do not link
# are left out of the configuration.
CXX="${CXX:-g++-12}" cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DMEFF_SANITIZE_THREAD=ON -DMEFF_BUILD_RENDER=OFF -DMEFF_BUILD_TOOLS=OFF \
    -DMEFF_BUILD_SAMPLES=OFF -DMEFF_BUILD_BENCHMARKS=OFF "$@" >/dev/null
nice cmake --build "$BUILD_DIR" -j2 --target meff_system_tests meff_scene_tests

# halt_on_error: the first report stops the run with TSan's exit code (66), so it cannot pass
# unnoticed among Catch2's output; second_deadlock_stack gives both stacks of a lock-order
# report.
export TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1${TSAN_OPTIONS:+ $TSAN_OPTIONS}"
log="$BUILD_DIR/tsan.log"
run_tests() {
    set +e
    local status=0
    : >"$log"
    for program in meff_system_tests meff_scene_tests; do
        "$@" "$BUILD_DIR/tests/$program" "[threads]" 2>&1 | tee -a "$log"
        local rc=${PIPESTATUS[0]}
        [ "$rc" -eq 0 ] || status=$rc
    done
    set -e
    return "$status"
}
status=0
run_tests nice || status=$?
# On kernels that randomize mmap with more bits than TSan's fixed memory layout allows (e.g.
# vm.mmap_rnd_bits=32), its runtime stops at start with "unexpected memory mapping"; run again
# without address-space randomization, which that layout does not need. (The kernel this was
# written on, 6.18 with 28 bits, starts it without this.)
if grep -q "unexpected memory mapping" "$log"; then
    echo "== TSan runtime could not start; again under setarch -R (no ASLR) =="
    status=0
    run_tests nice setarch "$(uname -m)" -R || status=$?
fi
if grep -q "WARNING: ThreadSanitizer" "$log"; then
    echo "== ThreadSanitizer reported (see $log) =="
    exit 1
fi
exit "$status"
