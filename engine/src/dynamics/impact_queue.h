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
//     refreshes, the cached impacts of its island's dynamic bodies, whether its bodies and their
//     neighbours are awake, and the contacts it creates (each one of a body it moved). The
//     contacts of those bodies are listed as changed; every other contact is as the last search
//     left it;
//   - the listed contacts are examined in contact-list order (newest first: Contact::serial),
//     so that the impacts computed (and the sweeps they advance) are the walk's, in the walk's
//     order; each one still valid enters a heap ordered by alpha, then list order — the walk's
//     "first smallest";
//   - an entry goes stale when its contact is listed again (a version per contact).
//
// A user callback that can run during the stage (pre-solve, custom filter) may wake any body:
// with one installed every candidate is listed after every event, which is the walk restricted
// to the candidates.
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

    /// The contacts listed since the last call, in contact-list order. Each one's earlier entry
    /// is stale; Push puts back those that still have an impact.
    const std::vector<std::int32_t>& TakeChanged(const WorldState& world);

    /// A contact's impact at alpha (a fraction of the step). Impacts the stage would not act on
    /// (alpha > 1 − 10ε, as b2World::SolveTOI's stop test, or NaN) are not kept.
    void Push(const WorldState& world, std::int32_t contactIndex, Real alpha);

    /// The earliest impact (the first in list order among equal alphas), removed from the
    /// queue, or kNullIndex for none.
    std::int32_t PopFirst(Real& alpha);

    /// After an event on contactIndex, and the contacts it created: lists the contacts it may
    /// have changed (see above).
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
    void List(std::int32_t contactIndex);
    void ListSweptContactsOf(const WorldState& world, std::int32_t bodyIndex);
    void Grow(std::size_t contactCount);

    std::vector<Entry> m_heap;
    std::vector<std::int32_t> m_changed; ///< listed since the last TakeChanged
    std::vector<std::int32_t> m_taken;   ///< what TakeChanged returned
    /// By contact index:
    std::vector<std::uint32_t> m_version;  ///< bumped each time the contact is taken
    std::vector<std::uint32_t> m_listedAt; ///< the round that last listed it
    std::uint32_t m_round = 0;
    bool m_listAll = false; ///< a user callback may run: list every candidate each event
};

} // namespace meff::detail
