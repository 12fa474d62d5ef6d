// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// The continuous stage's queue of candidate impacts: which contact has the earliest time of
// impact, found without walking every contact after every event.
//
// Box2D 2.4.1's b2World::SolveTOI finds each event by walking the whole contact list: a contact
// with a cached impact (Contact::Toi) gives it, one without has it computed (which advances the
// sweep of whichever of its bodies is behind), and the first contact in list order with the
// smallest alpha wins. Walking 70,000 contacts for each of thousands of events a step made that
// search nearly all of a churning scene's step. The queue gives the same answer, bit for bit:
//
//   - only swept contacts (Contact::Swept, kept in WorldState::sweptContacts) are candidates:
//     the others never have an impact;
//   - an event changes only the contacts around it: the flags and counts of the contacts it
//     refreshes (all on its dynamic bodies), the cached impacts of its island's dynamic bodies,
//     which bodies are awake (its own, and the neighbours its island may take), and the contacts
//     it creates (each one of a body it moved). The swept contacts of its dynamic bodies, and of
//     a kinematic one it woke, are listed as changed; every other contact is as the last search
//     left it;
//   - the listed contacts are examined in contact-list order (newest first: Contact::serial),
//     so that the impacts computed (and the sweeps they advance) are the walk's, in the walk's
//     order; each one's entry in a heap ordered by alpha, then list order (the walk's "first
//     smallest"), is kept, replaced or dropped;
//   - an entry goes stale when a new one replaces it or its contact is dropped (a version per
//     contact).
//
// A user callback that can run during the stage (pre-solve, custom filter) may change any
// body's awake state: with one installed every candidate is listed after every event, which is
// the walk restricted to the candidates.
#pragma once

#include "meff/math.h"

#include <cstdint>
#include <vector>

namespace meff::detail
{

struct WorldState;

class ImpactQueue
{
  public:
    /// Starts a step's search: every candidate is listed as changed.
    void Begin(const WorldState& world);

    /// The contacts listed since the last call, in contact-list order, for Set or Drop each.
    const std::vector<std::int32_t>& TakeChanged(const WorldState& world);

    /// A listed contact's impact at alpha (a fraction of the step). Impacts the stage would not
    /// act on (alpha > 1 − 10ε, as b2World::SolveTOI's stop test, or NaN) are dropped.
    void Set(const WorldState& world, std::int32_t contactIndex, Real alpha);
    /// A listed contact with no impact to act on (not eligible, or not swept now).
    void Drop(std::int32_t contactIndex);

    /// The earliest impact (the first in list order among equal alphas), removed from the
    /// queue, or kNullIndex for none.
    std::int32_t PopFirst(Real& alpha);

    /// Before an event on contactIndex: notes the kinematic bodies it may wake that sleep.
    void BeforeEvent(const WorldState& world, std::int32_t contactIndex);
    /// After the event, and the contacts it created: lists the contacts it may have changed.
    void EventDone(const WorldState& world, std::int32_t contactIndex);

  private:
    struct Entry
    {
        Real alpha;
        std::uint64_t serial; ///< the contact's: the walk meets larger ones first
        std::int32_t contact;
        std::uint32_t version;
    };
    static bool Later(const Entry& a, const Entry& b);

    void NextRound();
    void List(std::int32_t contactIndex); ///< not with m_listAll: every candidate is taken then
    void ListSweptContactsOf(const WorldState& world, std::int32_t bodyIndex);
    void Grow(std::size_t contactCount);

    std::vector<Entry> m_heap;
    std::vector<std::int32_t> m_changed; ///< listed since the last TakeChanged
    std::vector<std::int32_t> m_taken;   ///< what TakeChanged returned
    std::vector<std::int32_t> m_asleep;  ///< BeforeEvent's sleeping kinematic bodies
    /// With m_listAll: every candidate in list order, and how many of sweptContacts it holds.
    std::vector<std::int32_t> m_all;
    std::size_t m_allCount = 0;
    /// By contact index:
    std::vector<std::uint32_t> m_version;  ///< of its live entry; bumped when it goes stale
    std::vector<Real> m_liveAlpha;         ///< its live entry's alpha
    std::vector<std::uint8_t> m_live;      ///< it has a live entry in the heap
    std::vector<std::uint32_t> m_listedAt; ///< the round that last listed it
    std::uint32_t m_round = 0;
    bool m_listAll = false; ///< a user callback may run: list every candidate each event
};

} // namespace meff::detail
