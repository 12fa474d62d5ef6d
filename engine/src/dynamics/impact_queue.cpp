// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
#include "dynamics/impact_queue.h"

#include "dynamics/impact_event.h"
#include "dynamics/world_state.h"

#include <algorithm>

namespace meff::detail
{

namespace
{

/// b2World::SolveTOI's stop test: an earliest impact later than this ends the stage.
constexpr Real kLastImpact = Real(1) - Real(10) * kEpsilon;

} // namespace

bool ImpactQueue::Later(const Entry& a, const Entry& b)
{
    return a.alpha > b.alpha || (a.alpha == b.alpha && a.serial < b.serial);
}

void ImpactQueue::Begin(const WorldState& world)
{
    m_listAll = static_cast<bool>(world.preSolve) || static_cast<bool>(world.customFilter);
    m_heap.clear();
    m_changed.clear();
    Grow(world.contacts.size());
    std::fill(m_live.begin(), m_live.end(), std::uint8_t{0});
    NextRound(); // a step that threw mid-stage may have left contacts listed
    m_all.clear();
    m_allCount = 0;
    if (!m_listAll) // else TakeChanged takes every candidate
    {
        for (const std::int32_t c : world.sweptContacts)
        {
            List(c);
        }
    }
}

const std::vector<std::int32_t>& ImpactQueue::TakeChanged(const WorldState& world)
{
    Grow(world.contacts.size()); // the last event may have made contacts
    const auto newestFirst = [&world](std::int32_t a, std::int32_t b)
    { return world.contacts[a].serial > world.contacts[b].serial; };
    if (m_listAll)
    {
        // Every candidate, in list order. No contact is destroyed during the stage, and those
        // it makes are appended to sweptContacts and are newer than all before: sorted, they
        // go in front of the order kept from the last call.
        const auto fresh = world.sweptContacts.begin() + static_cast<std::ptrdiff_t>(m_allCount);
        m_changed.assign(fresh, world.sweptContacts.end());
        std::sort(m_changed.begin(), m_changed.end(), newestFirst);
        m_all.insert(m_all.begin(), m_changed.begin(), m_changed.end());
        m_allCount = world.sweptContacts.size();
        m_changed.clear();
        NextRound();
        return m_all;
    }
    std::sort(m_changed.begin(), m_changed.end(), newestFirst);
    m_taken.swap(m_changed);
    m_changed.clear();
    NextRound(); // a contact listed from now on goes into the next batch
    return m_taken;
}

void ImpactQueue::Set(const WorldState& world, std::int32_t contactIndex, Real alpha)
{
    if (!(alpha <= kLastImpact))
    {
        Drop(contactIndex);
        return;
    }
    const auto i = static_cast<std::size_t>(contactIndex);
    if (m_live[i] != 0 && m_liveAlpha[i] == alpha)
    {
        return; // its entry stands: same alpha, same place in the list
    }
    ++m_version[i];
    m_live[i] = 1;
    m_liveAlpha[i] = alpha;
    m_heap.push_back({alpha, world.contacts[i].serial, contactIndex, m_version[i]});
    std::push_heap(m_heap.begin(), m_heap.end(), Later);
}

void ImpactQueue::Drop(std::int32_t contactIndex)
{
    const auto i = static_cast<std::size_t>(contactIndex);
    if (m_live[i] != 0)
    {
        ++m_version[i];
        m_live[i] = 0;
    }
}

std::int32_t ImpactQueue::PopFirst(Real& alpha)
{
    while (!m_heap.empty())
    {
        std::pop_heap(m_heap.begin(), m_heap.end(), Later);
        const Entry entry = m_heap.back();
        m_heap.pop_back();
        const auto i = static_cast<std::size_t>(entry.contact);
        if (m_live[i] != 0 && entry.version == m_version[i])
        {
            m_live[i] = 0;
            alpha = entry.alpha;
            return entry.contact;
        }
    }
    alpha = 1;
    return kNullIndex;
}

void ImpactQueue::BeforeEvent(const WorldState& world, std::int32_t contactIndex)
{
    m_asleep.clear();
    if (m_listAll)
    {
        return;
    }
    ForEachImpactEventBody(world, contactIndex,
                           [&](std::int32_t b)
                           {
                               const Body& body = world.bodies[b];
                               if (body.type == BodyType::Kinematic && !body.awake)
                               {
                                   m_asleep.push_back(b);
                               }
                           });
}

void ImpactQueue::EventDone(const WorldState& world, std::int32_t contactIndex)
{
    Grow(world.contacts.size()); // the event may have made contacts
    if (m_listAll)
    {
        return; // TakeChanged takes every candidate
    }
    // A dynamic body's contacts may have been refreshed, lost their cached impacts, gained a
    // new contact or seen it wake; a kinematic body's other contacts change only if it woke.
    ForEachImpactEventBody(world, contactIndex,
                           [&](std::int32_t b)
                           {
                               if (world.bodies[b].type == BodyType::Dynamic)
                               {
                                   ListSweptContactsOf(world, b);
                               }
                           });
    for (const std::int32_t b : m_asleep)
    {
        if (world.bodies[b].awake)
        {
            ListSweptContactsOf(world, b);
        }
    }
}

void ImpactQueue::NextRound()
{
    if (++m_round == 0) // wrapped: no contact may look listed in the new round
    {
        std::fill(m_listedAt.begin(), m_listedAt.end(), 0U);
        m_round = 1;
    }
}

void ImpactQueue::List(std::int32_t contactIndex)
{
    const auto i = static_cast<std::size_t>(contactIndex);
    if (m_listedAt[i] != m_round)
    {
        m_listedAt[i] = m_round;
        m_changed.push_back(contactIndex);
    }
}

void ImpactQueue::ListSweptContactsOf(const WorldState& world, std::int32_t bodyIndex)
{
    for (std::int32_t key = world.bodies[bodyIndex].contactList; key != kNullIndex;)
    {
        const std::int32_t c = EdgeOwner(key);
        const Contact& contact = world.contacts[c];
        key = contact.edges[EdgeSide(key)].next;
        if ((contact.flags & Contact::Swept) != 0)
        {
            List(c);
        }
    }
}

void ImpactQueue::Grow(std::size_t contactCount)
{
    if (m_version.size() < contactCount)
    {
        m_version.resize(contactCount);
        m_liveAlpha.resize(contactCount);
        m_live.resize(contactCount);
        m_listedAt.resize(contactCount);
    }
}

} // namespace meff::detail
