// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The world's pools of bodies, shapes, joints and chains: slots addressed by an id (index and
// generation, meff/ids.h), with a free list. A destroyed slot's index is reused by the next
// creation, newest freed first, and its generation goes up, so that an id of what was there
// before is refused instead of reaching the new occupant.
#pragma once

#include "core/report_error.h"
#include "meff/error.h"
#include "meff/ids.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace meff::detail
{

/// Slots of T (a struct with `std::uint32_t generation` and `bool alive`), dead or alive, and
/// the indices of the dead ones, addressed by Id<Tag> (BodyId for BodyTag, and so on).
/// The stages and solvers walk the slots by index (`operator[]`, `Slots()`), skipping dead
/// ones where it matters; World's calls go through ids.
template <typename T, typename Tag>
class Pool
{
  public:
    using IdType = Id<Tag>;

    T& operator[](std::size_t index) { return m_slots[index]; }
    const T& operator[](std::size_t index) const { return m_slots[index]; }
    std::size_t size() const { return m_slots.size(); }
    T* begin() { return m_slots.data(); }
    T* end() { return m_slots.data() + m_slots.size(); }
    const T* begin() const { return m_slots.data(); }
    const T* end() const { return m_slots.data() + m_slots.size(); }
    T* data() { return m_slots.data(); }
    const T* data() const { return m_slots.data(); }
    /// Every slot, dead or alive, by index.
    std::vector<T>& Slots() { return m_slots; }
    const std::vector<T>& Slots() const { return m_slots; }

    /// A new live slot: the most recently freed one, else one more at the end. It holds
    /// `value` (a value-initialised T by default), alive, with the slot's generation one above
    /// its last (1 for a new slot). Returns its id.
    IdType Allocate(T value = T{})
    {
        std::int32_t index;
        if (!m_free.empty())
        {
            index = m_free.back();
            m_free.pop_back();
        }
        else
        {
            index = static_cast<std::int32_t>(m_slots.size());
            m_slots.emplace_back();
        }
        T& slot = m_slots[std::size_t(index)];
        const std::uint32_t generation = slot.generation + 1;
        slot = std::move(value);
        slot.generation = generation;
        slot.alive = true;
        return IdType{index, generation};
    }

    /// Frees the live slot at `index`: it is dead, and the next Allocate reuses it.
    void Free(std::int32_t index)
    {
        m_slots[std::size_t(index)].alive = false;
        m_free.push_back(index);
    }

    /// Whether `id` names a live slot: not null, in range, alive, of the same generation.
    bool IsValid(IdType id) const
    {
        return id.index >= 0 && static_cast<std::size_t>(id.index) < m_slots.size() &&
               !id.IsNull() && m_slots[std::size_t(id.index)].alive &&
               m_slots[std::size_t(id.index)].generation == id.generation;
    }

    /// The live slot `id` names, or nullptr once it has reported InvalidArgument("[WHERE: ]
    /// invalid KIND id (index I, generation G): null, or already destroyed") for any other id
    /// (detail::ReportError: thrown with exceptions).
    T* Resolve(IdType id, const char* kind, const char* where = nullptr)
    {
        return RequireValid(id, kind, where) ? &m_slots[std::size_t(id.index)] : nullptr;
    }
    const T* Resolve(IdType id, const char* kind, const char* where = nullptr) const
    {
        return RequireValid(id, kind, where) ? &m_slots[std::size_t(id.index)] : nullptr;
    }

  private:
    [[nodiscard]] bool RequireValid(IdType id, const char* kind, const char* where) const
    {
        return IsValid(id) ||
               Refuse(InvalidArgument((where ? std::string(where) + ": " : std::string()) +
                                      "invalid " + kind + " id (index " + std::to_string(id.index) +
                                      ", generation " + std::to_string(id.generation) +
                                      "): null, or already destroyed"));
    }

    std::vector<T> m_slots;
    std::vector<std::int32_t> m_free; ///< dead slots' indices, the next to reuse last
};

} // namespace meff::detail
