// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Running the Python plotting scripts (validation/plot_*.py) from the `meff` subcommands that
// draw plots. Plots are optional: without python3 and matplotlib the data files are still
// written, and the caller says so.
#pragma once

#include <string>
#include <vector>

namespace meff::cli
{

/// Runs arguments[0] (looked up on PATH) with the rest as its arguments, its stdout and stderr
/// sent to /dev/null when `quiet`; returns its exit status, or -1 if it could not be run.
int RunProgram(const std::vector<std::string>& arguments, bool quiet);

/// A python3 that can import matplotlib ($MEFF_PYTHON, then python3 on PATH, then
/// /usr/bin/python3, where Debian's python3-matplotlib lives), or empty.
std::string FindPlottingPython();

} // namespace meff::cli
