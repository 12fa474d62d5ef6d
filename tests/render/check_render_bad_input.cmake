# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
# cmake -DMEFF=... -DOUTPUT_DIR=... "-DARGS=SCENE;OPTION;..." -P check_render_bad_input.cmake
# Passes when `meff render ARGS --out OUTPUT_DIR` (or ARGS alone when it has its own --out)
# exits with status 2 exactly, says why in one line on stderr, and leaves no frame file behind.
cmake_policy(SET CMP0057 NEW) # if(IN_LIST) in script mode
file(REMOVE_RECURSE ${OUTPUT_DIR})
if(NOT "--out" IN_LIST ARGS)
    list(APPEND ARGS --out ${OUTPUT_DIR})
endif()
execute_process(COMMAND ${MEFF} render ${ARGS}
    RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status STREQUAL "2")
    message(FATAL_ERROR "exit status ${status}, expected 2\n${out}${err}")
endif()
string(REGEX MATCHALL "\n" newlines "${err}")
list(LENGTH newlines count)
if(NOT count EQUAL 1 OR err MATCHES "^\n")
    message(FATAL_ERROR "expected a one-line error on stderr, got:\n${err}")
endif()
message(STATUS "stderr: ${err}")
file(GLOB_RECURSE leftovers ${OUTPUT_DIR}/*)
if(leftovers)
    message(FATAL_ERROR "files left behind: ${leftovers}")
endif()
