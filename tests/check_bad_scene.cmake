# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
# cmake -DMEFF=... -DSCENE=... -DEXPECTED=... -P check_bad_scene.cmake
# Passes when `meff run SCENE` exits with status 2, writes exactly the EXPECTED text to stderr
# and nothing to stdout.
execute_process(COMMAND ${MEFF} run ${SCENE}
    RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
file(READ ${EXPECTED} expected)
if(NOT status STREQUAL "2")
    message(FATAL_ERROR "exit status ${status}, expected 2\nstderr:\n${err}")
endif()
if(NOT err STREQUAL expected)
    message(FATAL_ERROR "stderr differs.\n--- got:\n${err}--- expected:\n${expected}")
endif()
if(NOT out STREQUAL "")
    message(FATAL_ERROR "unexpected stdout:\n${out}")
endif()
