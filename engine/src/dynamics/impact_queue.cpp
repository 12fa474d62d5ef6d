#include "dynamics/impact_queue.h"

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
    NextRound(); // a step that threw mid-stage may have left contacts listed
    for (const std::int32_t c : world.sweptContacts)
    {
        List(c);
    }
}

const std::vector<std::int32_t>& ImpactQueue::TakeChanged(const WorldState& world)
{
    if (m_listAll)
    {
        m_changed.assign(world.sweptContacts.begin(), world.sweptContacts.end());
    }
    std::sort(m_changed.begin(), m_changed.end(),
              [&world](std::int32_t a, std::int32_t b)
              { return world.contacts[a].serial > world.contacts[b].serial; });
    m_taken.swap(m_changed);
    m_changed.clear();
    for (const std::int32_t c : m_taken)
    {
        ++m_version[static_cast<std::size_t>(c)];
    }
    NextRound(); // a contact listed from now on goes into the next batch
    return m_taken;
}

void ImpactQueue::Push(const WorldState& world, std::int32_t contactIndex, Real alpha)
{
    if (!(alpha <= kLastImpact))
    {
        return;
    }
    const auto i = static_cast<std::size_t>(contactIndex);
    m_heap.push_back({alpha, world.contacts[i].serial, contactIndex, m_version[i]});
    std::push_heap(m_heap.begin(), m_heap.end(), Later);
}

std::int32_t ImpactQueue::PopFirst(Real& alpha)
{
    while (!m_heap.empty())
    {
        std::pop_heap(m_heap.begin(), m_heap.end(), Later);
        const Entry entry = m_heap.back();
        m_heap.pop_back();
        if (entry.version == m_version[static_cast<std::size_t>(entry.contact)])
        {
            alpha = entry.alpha;
            return entry.contact;
        }
    }
    alpha = 1;
    return kNullIndex;
}

void ImpactQueue::EventDone(const WorldState& world, std::int32_t contactIndex)
{
    if (m_listAll)
    {
        return; // TakeChanged takes every candidate
    }
    Grow(world.contacts.size()); // the event may have made contacts
    // The event refreshed and woke its two bodies; for a dynamic one it refreshed (and may have
    // woken the other side of) each contact its island may take, and the solved island's
    // dynamic bodies lost their cached impacts and may have made contacts. A static body
    // neither wakes nor loses them.
    const Contact& contact = world.contacts[contactIndex];
    for (const std::int32_t bodyIndex : {contact.bodyA, contact.bodyB})
    {
        const Body& body = world.bodies[bodyIndex];
        if (body.type == BodyType::Static)
        {
            continue;
        }
        ListSweptContactsOf(world, bodyIndex);
        if (body.type != BodyType::Dynamic)
        {
            continue; // the island takes neighbours of dynamic bodies only
        }
        for (std::int32_t key = body.contactList; key != kNullIndex;)
        {
            const Contact& neighbour = world.contacts[EdgeOwner(key)];
            const Edge& edge = neighbour.edges[EdgeSide(key)];
            key = edge.next;
            const Body& other = world.bodies[edge.other];
            const bool takenByIsland =
                !neighbour.IsSensor() && other.type != BodyType::Static &&
                (other.type != BodyType::Dynamic || body.bullet || other.bullet);
            if (takenByIsland)
            {
                ListSweptContactsOf(world, edge.other);
            }
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
    if (!m_listAll && m_listedAt[i] != m_round)
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
        m_listedAt.resize(contactCount);
    }
}

} // namespace meff::detail
