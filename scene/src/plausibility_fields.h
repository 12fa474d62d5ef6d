// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The scene file's "plausibility" section (docs/scene-format.md, "plausibility"): the
// thresholds of the physics checks `meff validate` applies to every back end.
#pragma once

#include "json_document.h"

namespace meff::scene_detail
{

/// Reads "plausibility" into `plausibility` (defaults kept for absent fields), reporting each
/// bad value with its field path.
void ReadPlausibility(ObjectReader& reader, ScenePlausibility& plausibility);

} // namespace meff::scene_detail
