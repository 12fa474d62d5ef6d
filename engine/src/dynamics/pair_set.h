// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The set of shape pairs that have a contact (contact_manager.cpp: "does this pair have a
// contact already?" for every pair the broad phase finds, thousands per step). Open addressing
// with linear probing in one array of keys: a look-up reads one or two cache lines where a
// node-based set follows a bucket's chain, and inserting allocates only when the table grows.
// Erasing shifts the following keys back, so no tombstones slow later look-ups. The table
// never shrinks: after a mass destruction it keeps its size, ready for the contacts to return.
#pragma once

#include <cassert>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace meff::detail
{

class PairSet
{
  public:
    /// 0 is never a key: it marks an empty slot.
    bool Contains(std::uint64_t key) const
    {
        if (m_slots.empty())
        {
            return false;
        }
        for (std::size_t i = Home(key);; i = Next(i))
        {
            if (m_slots[i] == key)
            {
                return true;
            }
            if (m_slots[i] == 0)
            {
                return false;
            }
        }
    }

    /// Adds `key` (not 0); returns false when it was there already.
    bool Insert(std::uint64_t key)
    {
        assert(key != 0);
        // At most half full: probe runs stay short.
        if (2 * (m_count + 1) > m_slots.size())
        {
            Grow();
        }
        for (std::size_t i = Home(key);; i = Next(i))
        {
            if (m_slots[i] == key)
            {
                return false;
            }
            if (m_slots[i] == 0)
            {
                m_slots[i] = key;
                ++m_count;
                return true;
            }
        }
    }

    /// Removes `key`; returns false when it was not there.
    bool Erase(std::uint64_t key)
    {
        if (m_slots.empty())
        {
            return false;
        }
        std::size_t hole = Home(key);
        while (m_slots[hole] != key)
        {
            if (m_slots[hole] == 0)
            {
                return false;
            }
            hole = Next(hole);
        }
        // Close the hole: a later key of the same run moves into it unless its home lies
        // cyclically in (hole, j], where it would no longer be found from its home.
        for (std::size_t j = Next(hole); m_slots[j] != 0; j = Next(j))
        {
            const std::size_t home = Home(m_slots[j]);
            const bool homeInRun =
                hole < j ? (hole < home && home <= j) : (hole < home || home <= j);
            if (!homeInRun)
            {
                m_slots[hole] = m_slots[j];
                hole = j;
            }
        }
        m_slots[hole] = 0;
        --m_count;
        return true;
    }

    std::size_t Size() const { return m_count; }

  private:
    /// splitmix64's finaliser: shape pair keys differ in few bits, so they are mixed first.
    static std::uint64_t Mix(std::uint64_t x)
    {
        x ^= x >> 30;
        x *= 0xbf58476d1ce4e5b9ull;
        x ^= x >> 27;
        x *= 0x94d049bb133111ebull;
        return x ^ (x >> 31);
    }
    std::size_t Home(std::uint64_t key) const
    {
        return static_cast<std::size_t>(Mix(key)) & (m_slots.size() - 1);
    }
    std::size_t Next(std::size_t i) const { return (i + 1) & (m_slots.size() - 1); }

    void Grow()
    {
        std::vector<std::uint64_t> old(m_slots.empty() ? 32 : 2 * m_slots.size(), 0);
        old.swap(m_slots);
        m_count = 0;
        for (const std::uint64_t key : old)
        {
            if (key != 0)
            {
                Insert(key);
            }
        }
    }

    std::vector<std::uint64_t> m_slots; ///< power-of-two size, 0 = empty
    std::size_t m_count = 0;
};

} // namespace meff::detail
