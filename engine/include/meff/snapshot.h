// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// A world's whole state at one moment (World::TakeSnapshot, World::RestoreSnapshot).
#pragma once

#include <memory>

namespace meff
{

namespace detail
{
struct WorldState;
}

/// The whole state of a world at one moment — bodies, shapes, joints, contacts with their
/// warm-starting impulses, the broad phase — for World::RestoreSnapshot. Cheap to copy (shared).
class WorldSnapshot
{
  public:
    WorldSnapshot() = default;
    /// A default-constructed snapshot, which holds no world.
    bool IsEmpty() const { return m_state == nullptr; }

  private:
    friend class World;
    std::shared_ptr<const detail::WorldState> m_state;
};

} // namespace meff
