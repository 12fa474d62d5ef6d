// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// meff's state after a step in the comparison's terms (meff/validation.h's FrameSample): what
// the Box2D comparison and the baselines both sample.
#pragma once

#include "meff/scene.h"
#include "meff/validation.h"

#include <cstdint>
#include <unordered_map>

namespace meff::validation
{

/// Samples a built scene's world: bodies, contact points and joint reactions, by scene index.
class MeffSampler
{
  public:
    explicit MeffSampler(const BuiltScene& built);

    /// The state now; `invDt` turns the joints' last impulses into reactions.
    FrameSample Sample(Real invDt) const;

  private:
    /// Scene body index, shape index and chain child index of a shape.
    struct ShapeKey
    {
        std::size_t body = 0;
        std::size_t shape = 0;
        std::size_t child = 0;
    };

    const BuiltScene& m_built;
    std::unordered_map<std::int32_t, ShapeKey> m_shapeOf;
};

} // namespace meff::validation
