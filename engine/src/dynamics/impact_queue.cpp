#include "dynamics/impact_queue.h"

#include "dynamics/world_state.h"

#include <algorithm>

namespace meff::detail
{

namespace
{

/// b2World::SolveTOI's stop test: an earliest impact later than this ends the stage.
constexpr Real kLastImpact = Real(1) - Real(10) * kEpsilon;

/// A contact the stage sweeps: one side static, kinematic or a bullet, and no sensor. Fixed for
/// the contact's life: types, bullets and sensors are set at creation.
bool IsSwept(const WorldState& world, const Contact& contact)
{
    const Body& bodyA = world.bodies[contact.bodyA];
    const Body& bodyB = world.bodies[contact.bodyB];
    const bool sweptA = bodyA.bullet || bodyA.type != BodyType::Dynamic;
    const bool sweptB = bodyB.bullet || bodyB.type != BodyType::Dynamic;
    return !contact.IsSensor() && (sweptA || sweptB);
}

} // namespace

bool ImpactQueue::Later(const Entry& a, const Entry& b)
{
    return a.alpha > b.alpha || (a.alpha == b.alpha && a.order > b.order);
}

void ImpactQueue::Begin(const WorldState& world)
{
    m_listAll = static_cast<bool>(world.preSolve) || static_cast<bool>(world.customFilter);
    m_heap.clear();
    m_candidates.clear();
    m_changed.clear();
    Grow(world.contacts.size());
    NextRound(); // a step that threw mid-stage may have left contacts listed
    std::int64_t position = 0;
    for (std::int32_t c = world.contactList; c != kNullIndex; c = world.contacts[c].next)
    {
        const auto i = static_cast<std::size_t>(c);
        m_order[i] = position++;
        m_swept[i] = IsSwept(world, world.contacts[c]) ? 1 : 0;
        if (m_swept[i] != 0)
        {
            m_candidates.push_back(c);
            List(c);
        }
    }
    m_nextFront = 0;
}

const std::vector<std::int32_t>& ImpactQueue::TakeChanged()
{
    if (!m_listAll)
    {
        std::sort(m_changed.begin(), m_changed.end(),
                  [this](std::int32_t a, std::int32_t b) {
                      return m_order[static_cast<std::size_t>(a)] <
                             m_order[static_cast<std::size_t>(b)];
                  });
        m_taken.swap(m_changed);
        m_changed.clear();
    }
    const std::vector<std::int32_t>& taken = m_listAll ? m_candidates : m_taken;
    for (const std::int32_t c : taken)
    {
        ++m_version[static_cast<std::size_t>(c)];
    }
    NextRound(); // a contact listed from now on goes into the next batch
    return taken;
}

void ImpactQueue::Push(std::int32_t contactIndex, Real alpha)
{
    if (!(alpha <= kLastImpact))
    {
        return;
    }
    const auto i = static_cast<std::size_t>(contactIndex);
    m_heap.push_back({alpha, m_order[i], contactIndex, m_version[i]});
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
    // The event refreshed and woke its two bodies; for a dynamic one it refreshed (and may have
    // woken the other side of) each contact its island may take, and the solved island's
    // dynamic bodies lost their cached impacts. A static body neither wakes nor loses them.
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

void ImpactQueue::AddNewContacts(const WorldState& world, std::int32_t oldHead)
{
    Grow(world.contacts.size());
    // Newest first at the list's front: number them from the last, each before the one after.
    m_fresh.clear();
    for (std::int32_t c = world.contactList; c != oldHead; c = world.contacts[c].next)
    {
        m_fresh.push_back(c);
    }
    for (auto it = m_fresh.rbegin(); it != m_fresh.rend(); ++it)
    {
        const auto i = static_cast<std::size_t>(*it);
        m_order[i] = --m_nextFront;
        m_swept[i] = IsSwept(world, world.contacts[*it]) ? 1 : 0;
    }
    std::erase_if(m_fresh,
                  [this](std::int32_t c) { return m_swept[static_cast<std::size_t>(c)] == 0; });
    m_candidates.insert(m_candidates.begin(), m_fresh.begin(), m_fresh.end());
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
        key = world.contacts[c].edges[EdgeSide(key)].next;
        if (m_swept[static_cast<std::size_t>(c)] != 0)
        {
            List(c);
        }
    }
}

void ImpactQueue::Grow(std::size_t contactCount)
{
    if (m_order.size() < contactCount)
    {
        m_order.resize(contactCount);
        m_version.resize(contactCount);
        m_listedAt.resize(contactCount);
        m_swept.resize(contactCount);
    }
}

} // namespace meff::detail
