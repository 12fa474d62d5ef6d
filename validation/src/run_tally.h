// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// A run's frames added up into its ValidationResult: the maxima, the counts and the first
// divergence, whatever the reference (Box2D 2.4.1 or a recorded baseline).
#pragma once

#include "meff/validation.h"

namespace meff::validation
{

/// Compares meff's frame with the reference's, adds it to result.perFrame, the maxima and the
/// counts, and records the first frame that exceeds a tolerance (result.tolerances) as the
/// divergence.
void TallyFrame(ValidationResult& result, const Scene& scene, int frame, const FrameSample& meff,
                const FrameSample& reference, double dt);

} // namespace meff::validation
