# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
# `cmake --install BUILD [--prefix DIR]`: the libraries that were built, their headers, the
# CMake package (find_package(meff CONFIG): meffConfig.cmake, meffConfigVersion.cmake and the
# targets meff::engine, and meff::scene, meff::validation, meff::render when built) and a
# pkg-config file for the engine (meff.pc), and the licence files (LICENSE, THIRD_PARTY_NOTICES:
# Box2D 2.4.1's MIT notice) into the documentation folder, share/doc/meff by default.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(MEFF_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/meff)
set(MEFF_INSTALLED_TARGETS meff_engine)
install(DIRECTORY engine/include/meff DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_SOURCE_DIR}/THIRD_PARTY_NOTICES
    DESTINATION ${CMAKE_INSTALL_DOCDIR})
# The optional libraries and their one or two headers each, when they were built.
foreach(component IN ITEMS scene validation render)
    if(TARGET meff_${component})
        list(APPEND MEFF_INSTALLED_TARGETS meff_${component})
        install(DIRECTORY ${component}/include/meff DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
    endif()
endforeach()
set(MEFF_INSTALLED_COMPONENTS ${MEFF_INSTALLED_TARGETS})
list(TRANSFORM MEFF_INSTALLED_COMPONENTS REPLACE "^meff_" "")

# The meff tool, for meff_add_validation_tests (cmake/MeffValidationTests.cmake): imported by
# the package as meff::meff.
if(TARGET meff)
    list(APPEND MEFF_INSTALLED_TARGETS meff)
    install(FILES ${CMAKE_CURRENT_LIST_DIR}/MeffValidationTests.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/meff)
endif()
install(TARGETS ${MEFF_INSTALLED_TARGETS} EXPORT meffTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
    INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT meffTargets NAMESPACE meff:: DESTINATION ${MEFF_INSTALL_CMAKEDIR})

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/meffConfig.cmake.in
    ${CMAKE_CURRENT_BINARY_DIR}/meffConfig.cmake INSTALL_DESTINATION ${MEFF_INSTALL_CMAKEDIR})
# 0.x: a new minor version may change the API.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/meffConfigVersion.cmake
    COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/meffConfig.cmake
    ${CMAKE_CURRENT_BINARY_DIR}/meffConfigVersion.cmake DESTINATION ${MEFF_INSTALL_CMAKEDIR})

# pkg-config: the engine alone, with what its users must compile with.
set(MEFF_PC_CFLAGS "-ffp-contract=off")
if(MEFF_DOUBLE)
    string(APPEND MEFF_PC_CFLAGS " -DMEFF_DOUBLE=1")
endif()
if(MEFF_AVX2)
    string(APPEND MEFF_PC_CFLAGS " -mavx2")
endif()
if(NOT MEFF_EXCEPTIONS)
    string(APPEND MEFF_PC_CFLAGS " -DMEFF_EXCEPTIONS=0")
endif()
# Relocatable: the prefix is found from where the file is, so `--prefix` works at install time.
file(RELATIVE_PATH MEFF_PC_TO_PREFIX "/meff/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/meff")
set(MEFF_PC_PREFIX "\${pcfiledir}/${MEFF_PC_TO_PREFIX}")
set(MEFF_PC_LIBDIR "\${prefix}/${CMAKE_INSTALL_LIBDIR}")
set(MEFF_PC_INCLUDEDIR "\${prefix}/${CMAKE_INSTALL_INCLUDEDIR}")
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}" OR IS_ABSOLUTE "${CMAKE_INSTALL_INCLUDEDIR}")
    set(MEFF_PC_PREFIX "${CMAKE_INSTALL_PREFIX}")
    set(MEFF_PC_LIBDIR "${CMAKE_INSTALL_FULL_LIBDIR}")
    set(MEFF_PC_INCLUDEDIR "${CMAKE_INSTALL_FULL_INCLUDEDIR}")
endif()
configure_file(${CMAKE_CURRENT_LIST_DIR}/meff.pc.in ${CMAKE_CURRENT_BINARY_DIR}/meff.pc @ONLY)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/meff.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
