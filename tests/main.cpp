// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Catch2's main().
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
