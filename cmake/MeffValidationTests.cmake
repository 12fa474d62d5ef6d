# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
# meff_add_validation_tests(DIR [NAME_PREFIX PREFIX] [FORMAT auto|meff|b2djson] [FRAMES N]
#                           [JUNIT_DIR DIR] [LABELS LABEL...] [ARGS ARG...])
#
# Turns a game's folder of scenes (meff scene files or b2dJson levels, *.json) into CTest
# tests, one per file: `meff validate FILE`, which passes when meff agrees with Box2D 2.4.1 on
# it (exit status 0) and fails with the divergence frame, quantity and both engines' values
# otherwise. Installed with meff's CMake package (find_package(meff) includes this file) and
# available to a build that adds meff's source tree.
#
#   DIR          the folder, relative to the current source directory; its *.json files are
#                globbed when the game is configured (CONFIGURE_DEPENDS: a new file is picked
#                up at the next build)
#   NAME_PREFIX  test names are PREFIX<file name without .json> (default "meff.validate.")
#   FORMAT       --format for every file (default: auto, by each file's content)
#   FRAMES       --frames: steps to compare (default: each scene's own)
#   JUNIT_DIR    also write JUNIT_DIR/<name>.xml, one JUnit file per test
#   LABELS       CTest labels added to "meff" and "validation"
#   ARGS         further arguments for `meff validate` (e.g. --block-solver off)
#
# The meff tool is MEFF_EXECUTABLE when set, else the package's imported meff::meff, else the
# meff target of meff's own build. Each test validates one scene on one thread (--jobs 1):
# `ctest -j N` spreads the tests over cores.
function(meff_add_validation_tests dir)
    cmake_parse_arguments(PARSE_ARGV 1 arg "" "NAME_PREFIX;FORMAT;FRAMES;JUNIT_DIR"
        "LABELS;ARGS")
    if(arg_UNPARSED_ARGUMENTS)
        message(FATAL_ERROR "meff_add_validation_tests: unknown arguments: "
            "${arg_UNPARSED_ARGUMENTS}")
    endif()
    get_filename_component(dir "${dir}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
    if(NOT IS_DIRECTORY "${dir}")
        message(FATAL_ERROR "meff_add_validation_tests: ${dir} is not a folder")
    endif()
    file(GLOB scenes CONFIGURE_DEPENDS "${dir}/*.json")
    list(SORT scenes)
    if(NOT scenes)
        message(FATAL_ERROR "meff_add_validation_tests: ${dir} holds no *.json scene")
    endif()
    if(DEFINED MEFF_EXECUTABLE)
        set(meff "${MEFF_EXECUTABLE}")
    elseif(TARGET meff::meff)
        set(meff "$<TARGET_FILE:meff::meff>")
    elseif(TARGET meff)
        set(meff "$<TARGET_FILE:meff>")
    else()
        message(FATAL_ERROR "meff_add_validation_tests: no meff tool: install meff with its "
            "tools (MEFF_BUILD_TOOLS=ON) or set MEFF_EXECUTABLE")
    endif()
    if(NOT DEFINED arg_NAME_PREFIX)
        set(arg_NAME_PREFIX "meff.validate.")
    endif()
    set(options --no-plot --jobs 1)
    if(arg_FORMAT)
        list(APPEND options --format ${arg_FORMAT})
    endif()
    if(DEFINED arg_FRAMES)
        list(APPEND options --frames ${arg_FRAMES})
    endif()
    if(arg_JUNIT_DIR)
        file(MAKE_DIRECTORY "${arg_JUNIT_DIR}")
    endif()
    foreach(scene IN LISTS scenes)
        get_filename_component(name "${scene}" NAME_WE)
        set(junit)
        if(arg_JUNIT_DIR)
            set(junit --junit "${arg_JUNIT_DIR}/${name}.xml")
        endif()
        add_test(NAME "${arg_NAME_PREFIX}${name}"
            COMMAND "${meff}" validate "${scene}" ${options} ${junit} ${arg_ARGS})
        set_tests_properties("${arg_NAME_PREFIX}${name}" PROPERTIES
            LABELS "meff;validation;${arg_LABELS}")
    endforeach()
endfunction()
