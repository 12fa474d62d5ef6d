#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
# meff used from outside its repository, as games use it (what CI runs after the test suite):
#   1. `cmake --install` of the build directory (default: build, already built) into a prefix,
#      with the licence files (LICENSE, THIRD_PARTY_NOTICES) in share/doc/meff;
#   2. a game configured against that prefix with find_package(meff CONFIG REQUIRED), built
#      and run, its sources compiled with -ffp-contract=off (meff::engine's usage requirement);
#   3. the same game built with pkg-config's flags for meff;
#   4. a game that adds meff's source tree with add_subdirectory: only the engine is built, with
#      every optional dependency of meff (Box2D, OSMesa, libpng, CLI11, nlohmann-json, Catch2,
#      Google Benchmark, Python) hidden from CMake, and the game's build type left alone;
#   5. a game's folder of levels turned into CTest tests by meff_add_validation_tests, run by
#      the installed meff tool.
# Everything is written under ${MEFF_CONSUMER_DIR:-build-consumers}.
set -euo pipefail
cd "$(dirname "$0")/.."
SOURCE=$PWD
BUILD="${1:-build}"
WORK="${MEFF_CONSUMER_DIR:-build-consumers}"
rm -rf "$WORK"
mkdir -p "$WORK"
WORK=$(cd "$WORK" && pwd)

# Fails unless the compile command of FILE in the compile database DB has -ffp-contract=off.
check_contract_off() {
    if ! grep -A3 "\"file\": \".*$2\"" "$1" | grep -q -- "-ffp-contract=off" &&
        ! grep -B3 "\"file\": \".*$2\"" "$1" | grep -q -- "-ffp-contract=off"; then
        echo "FAIL: $2 was not compiled with -ffp-contract=off ($1)" >&2
        exit 1
    fi
}

echo "== 1. cmake --install $BUILD --prefix $WORK/prefix =="
cmake --install "$BUILD" --prefix "$WORK/prefix" >/dev/null
ls "$WORK/prefix/lib/cmake/meff" "$WORK/prefix/lib/pkgconfig"
# The licence and Box2D 2.4.1's notice travel with every installation.
for file in LICENSE THIRD_PARTY_NOTICES; do
    if ! cmp -s "$file" "$WORK/prefix/share/doc/meff/$file"; then
        echo "FAIL: $file is not installed as share/doc/meff/$file" >&2
        exit 1
    fi
done
grep -q "Copyright (c) 2019 Erin Catto" "$WORK/prefix/share/doc/meff/THIRD_PARTY_NOTICES"

echo "== 2. find_package(meff CONFIG REQUIRED COMPONENTS scene) =="
cmake -S tests/consumers/find_package -B "$WORK/find_package" \
    -DCMAKE_PREFIX_PATH="$WORK/prefix" >/dev/null
cmake --build "$WORK/find_package" -j"$(nproc)" >/dev/null
check_contract_off "$WORK/find_package/compile_commands.json" game.cpp
"$WORK/find_package/game"
"$WORK/find_package/scene_game"

echo "== 3. pkg-config --cflags --libs meff =="
flags=$(PKG_CONFIG_PATH="$WORK/prefix/lib/pkgconfig" pkg-config --cflags --libs meff)
echo "$flags"
case " $flags " in *" -ffp-contract=off "*) ;; *) echo "FAIL: no -ffp-contract=off" >&2; exit 1 ;; esac
# pkg-config and the CMake package carry the project's version.
project_version=$(sed -n 's/^CMAKE_PROJECT_VERSION:STATIC=//p' "$BUILD/CMakeCache.txt")
pc_version=$(PKG_CONFIG_PATH="$WORK/prefix/lib/pkgconfig" pkg-config --modversion meff)
if [ -z "$project_version" ] || [ "$pc_version" != "$project_version" ] ||
    ! grep -q "set(PACKAGE_VERSION \"$project_version\")" "$WORK/prefix/lib/cmake/meff/meffConfigVersion.cmake"; then
    echo "FAIL: version: project '$project_version', meff.pc '$pc_version'" >&2
    exit 1
fi
echo "version $pc_version"
# An AVX2 build (MEFF_AVX2) needs its users compiled for AVX2 too, as meff::engine says.
if grep -q '^MEFF_AVX2:BOOL=ON$' "$BUILD/CMakeCache.txt"; then
    case " $flags " in *" -mavx2 "*) ;; *) echo "FAIL: an AVX2 build without -mavx2" >&2; exit 1 ;; esac
fi
# shellcheck disable=SC2086 # the flags are words
${CXX:-c++} -std=c++20 -O2 tests/consumers/game.cpp $flags -o "$WORK/pkg_config_game"
"$WORK/pkg_config_game"

echo "== 4. add_subdirectory(meff) with no optional dependency to be found =="
hidden=()
for package in box2d PkgConfig PNG CLI11 nlohmann_json Catch2 benchmark Python3; do
    hidden+=("-DCMAKE_DISABLE_FIND_PACKAGE_$package=ON")
done
cmake -S tests/consumers/add_subdirectory -B "$WORK/add_subdirectory" \
    -DMEFF_SOURCE_DIR="$SOURCE" "${hidden[@]}" --no-warn-unused-cli >/dev/null
cmake --build "$WORK/add_subdirectory" -j"$(nproc)" >/dev/null
check_contract_off "$WORK/add_subdirectory/compile_commands.json" game.cpp
"$WORK/add_subdirectory/game"

echo "== 5. meff_add_validation_tests: a game's folder of levels as CTest tests =="
cmake -S tests/consumers/validation_tests -B "$WORK/validation_tests" \
    -DCMAKE_PREFIX_PATH="$WORK/prefix" -DLEVELS="$SOURCE/tests/b2djson" >/dev/null
ctest --test-dir "$WORK/validation_tests" --output-on-failure
ls "$WORK/validation_tests/junit"

echo "All consumer builds passed."
