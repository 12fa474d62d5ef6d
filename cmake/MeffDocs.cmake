# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
# The API reference: `cmake --build BUILD --target docs` runs Doxygen (Debian's `doxygen`
# package) over the engine's public headers into BUILD/docs/html/index.html. Every public
# symbol of engine/include/meff must have a `///` comment: an undocumented one, or any other
# Doxygen warning, fails the build (WARN_AS_ERROR = FAIL_ON_WARNINGS lists them all first).
# Without Doxygen there is no `docs` target, and the rest of the build is unchanged.
find_package(Doxygen QUIET)
if(NOT DOXYGEN_FOUND)
    message(STATUS "Doxygen not found: no `docs` target (the API reference)")
    return()
endif()
set(DOXYGEN_PROJECT_BRIEF "A 2D rigid-body physics engine")
set(DOXYGEN_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/docs)
set(DOXYGEN_GENERATE_LATEX NO)
set(DOXYGEN_HAVE_DOT NO)
set(DOXYGEN_QUIET YES)
set(DOXYGEN_EXTRACT_ALL NO)
set(DOXYGEN_WARN_IF_UNDOCUMENTED YES)
set(DOXYGEN_WARN_IF_DOC_ERROR YES)
set(DOXYGEN_WARN_AS_ERROR FAIL_ON_WARNINGS)
# The engine's internals (meff::detail) are not part of the API.
set(DOXYGEN_EXCLUDE_SYMBOLS meff::detail detail)
set(DOXYGEN_STRIP_FROM_PATH ${PROJECT_SOURCE_DIR}/engine/include)
set(DOXYGEN_FULL_PATH_NAMES YES)
doxygen_add_docs(docs ${PROJECT_SOURCE_DIR}/engine/include/meff
    COMMENT "The API reference (Doxygen) into ${CMAKE_BINARY_DIR}/docs/html")
# CI builds the reference as a test (label docs), so a symbol added without its comment fails.
if(MEFF_BUILD_TESTS)
    add_test(NAME docs.reference
        COMMAND ${CMAKE_COMMAND} --build ${CMAKE_BINARY_DIR} --target docs)
    set_tests_properties(docs.reference PROPERTIES LABELS docs)
endif()
