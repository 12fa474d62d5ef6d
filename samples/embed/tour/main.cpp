// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// meff_tour: runs every stop of the embedding tour and prints what a game would see.
#include "tour.h"

int main()
{
    meff::tour::RunOneWayPlatform(stdout);
    meff::tour::RunRayCast(stdout);
    meff::tour::RunCar(stdout);
    meff::tour::RunRollback(stdout);
    return 0;
}
