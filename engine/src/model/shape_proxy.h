// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The distance queries' proxy (meff/distance.h) of a world shape.
#pragma once

#include "meff/distance.h"

namespace meff::detail
{

struct Shape;

/// The GJK proxy of a world shape (its geometry and collision radius).
DistanceProxy MakeProxy(const Shape& shape);

} // namespace meff::detail
