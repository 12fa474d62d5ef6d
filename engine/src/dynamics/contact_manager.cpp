// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Contact lifecycle: created from broad-phase pairs, updated by the narrow phase, destroyed
// when the fat boxes part. Lists are kept newest first, as Box2D 2.4.1 does, because the island
// search — and so the solver — walks them in that order.
#include "dynamics/step_stages.h"

#include "dynamics/events.h"
#include "dynamics/pair_rules.h"
#include "dynamics/world_state.h"
#include "tasks/parallel_ranges.h"

#include <vector>

namespace meff::detail
{

namespace
{

/// Contact::Swept: what the continuous stage sweeps (Box2D 2.4.1's b2World::SolveTOI skips a
/// sensor and two ordinary dynamic bodies).
[[gnu::always_inline]] inline bool IsSwept(const WorldState& world, const Contact& contact)
{
    const Body& bodyA = world.bodies[contact.bodyA];
    const Body& bodyB = world.bodies[contact.bodyB];
    const bool sweptA = bodyA.bullet || bodyA.type != BodyType::Dynamic;
    const bool sweptB = bodyB.bullet || bodyB.type != BodyType::Dynamic;
    return !contact.IsSensor() && (sweptA || sweptB);
}

/// The user's filter (World::SetCustomFilterCallback), asked after the built-in rules.
bool CustomFilterAllows(WorldState& world, std::int32_t a, std::int32_t b)
{
    if (!world.customFilter)
    {
        return true;
    }
    const InUserCallback inside(world, "the custom filter");
    return world.customFilter(ShapeId{a, world.shapes[a].generation},
                              ShapeId{b, world.shapes[b].generation});
}

/// Collide's recycling (CollisionPolicy::recycleDistance): may this touching contact keep its
/// manifold for another step? Its points are stored in the bodies' own frames, so the solver
/// measures their separations at the bodies' new poses whatever happens here; what a kept
/// manifold can miss is a change of the touching features (a point that appears, a face that
/// takes over), which needs B to move relative to A: by less than the limit since the manifold
/// was computed (RelativeMotionBound). The pre-solve callback, which may change a manifold every
/// step, turns recycling off (Collide).
[[gnu::always_inline]] inline bool KeepsManifold(Real limit, const Contact& contact,
                                                 const Shape& shapeB, const Transform& xfA,
                                                 const Transform& xfB)
{
    constexpr std::uint32_t kMask = Contact::PoseKept | Contact::Touching | Contact::Sensor;
    constexpr std::uint32_t kKept = Contact::PoseKept | Contact::Touching;
    return (contact.flags & kMask) == kKept &&
           RelativeMotionBound(contact.keptPose, MulT(xfA, xfB), shapeB.reach) < limit;
}

void LinkEdge(WorldState& world, Body& body, std::int32_t contactIndex, int side)
{
    Contact& contact = world.contacts[contactIndex];
    Edge& edge = contact.edges[side];
    edge.prev = kNullIndex;
    edge.next = body.contactList;
    if (body.contactList != kNullIndex)
    {
        world.contacts[EdgeOwner(body.contactList)].edges[EdgeSide(body.contactList)].prev =
            EdgeKey(contactIndex, side);
    }
    body.contactList = EdgeKey(contactIndex, side);
}

void UnlinkEdge(WorldState& world, Body& body, std::int32_t contactIndex, int side)
{
    const Edge& edge = world.contacts[contactIndex].edges[side];
    if (edge.prev != kNullIndex)
    {
        world.contacts[EdgeOwner(edge.prev)].edges[EdgeSide(edge.prev)].next = edge.next;
    }
    if (edge.next != kNullIndex)
    {
        world.contacts[EdgeOwner(edge.next)].edges[EdgeSide(edge.next)].prev = edge.prev;
    }
    if (body.contactList == EdgeKey(contactIndex, side))
    {
        body.contactList = edge.next;
    }
}

} // namespace

namespace
{

/// CreateContact's first step: asks the user's filter, then orders the shapes as the manifold
/// functions take them (sA, sB); false when no contact is made.
[[gnu::always_inline]] inline bool ContactShapes(WorldState& world, std::int32_t shapeIndexA,
                                                 std::int32_t shapeIndexB, std::int32_t& sA,
                                                 std::int32_t& sB)
{
    if (!CustomFilterAllows(world, shapeIndexA, shapeIndexB))
    {
        return false;
    }
    bool swap = false;
    if (!ContactOrder(world.shapes[shapeIndexA].type, world.shapes[shapeIndexB].type, swap))
    {
        return false;
    }
    sA = swap ? shapeIndexB : shapeIndexA;
    sB = swap ? shapeIndexA : shapeIndexB;
    return true;
}

/// The second: a slot for the contact (the free list's last, or a new one), its index, and the
/// pair in the set of existing contacts.
[[gnu::always_inline]] inline std::int32_t TakeContactSlot(WorldState& world, std::int32_t sA,
                                                           std::int32_t sB)
{
    std::int32_t index;
    if (!world.freeContacts.empty())
    {
        index = world.freeContacts.back();
        world.freeContacts.pop_back();
    }
    else
    {
        index = static_cast<std::int32_t>(world.contacts.size());
        world.contacts.emplace_back();
    }
    world.contactPairs.Insert(ShapePairKey(sA, sB));
    return index;
}

/// The third: the new contact's own fields from its shapes and bodies, all but its serial
/// number and the lists' links. Writes only the contact, so that new contacts can be made on
/// several threads at once (MakeContacts).
[[gnu::always_inline]] inline void InitContact(const WorldState& world, Contact& contact,
                                               std::int32_t sA, std::int32_t sB)
{
    contact = Contact{};
    contact.alive = true;
    contact.shapeA = sA;
    contact.shapeB = sB;
    contact.bodyA = world.shapes[sA].body;
    contact.bodyB = world.shapes[sB].body;
    const ShapeDef& defA = world.shapes[sA].def;
    const ShapeDef& defB = world.shapes[sB].def;
    contact.radiusA = world.shapes[sA].Radius();
    contact.radiusB = world.shapes[sB].Radius();
    contact.friction = MixFriction(defA.friction, defB.friction);
    contact.restitution = MixRestitution(defA.restitution, defB.restitution);
    contact.restitutionThreshold =
        MixRestitutionThreshold(defA.restitutionThreshold, defB.restitutionThreshold);
    contact.tangentSpeed = defA.tangentSpeed + defB.tangentSpeed;
    if (defA.rollingResistance > 0 || defB.rollingResistance > 0)
    {
        contact.rollingResistance =
            Max(defA.rollingResistance, defB.rollingResistance) *
            Max(world.shapes[sA].RollingRadius(), world.shapes[sB].RollingRadius());
    }
    if (defA.isSensor || defB.isSensor)
    {
        contact.flags |= Contact::Sensor;
    }
    if (defA.enableHitEvents || defB.enableHitEvents)
    {
        contact.flags |= Contact::HitEvents;
    }
    if (IsSwept(world, contact))
    {
        contact.flags |= Contact::Swept;
    }
}

/// The last: the serial number, the swept list, the contact list and the bodies' edges, the
/// count.
[[gnu::always_inline]] inline void LinkContact(WorldState& world, std::int32_t index)
{
    Contact& contact = world.contacts[index];
    contact.serial = ++world.contactSerial;
    if ((contact.flags & Contact::Swept) != 0)
    {
        contact.sweptSlot = static_cast<std::int32_t>(world.sweptContacts.size());
        world.sweptContacts.push_back(index);
    }

    contact.prev = kNullIndex;
    contact.next = world.contactList;
    if (world.contactList != kNullIndex)
    {
        world.contacts[world.contactList].prev = index;
    }
    world.contactList = index;

    contact.edges[0].other = contact.bodyB;
    contact.edges[1].other = contact.bodyA;
    LinkEdge(world, world.bodies[contact.bodyA], index, 0);
    LinkEdge(world, world.bodies[contact.bodyB], index, 1);
    ++world.contactCount;
}

} // namespace

/// New contacts to a range of MakeContacts' threaded part: a contact's fields cost about a
/// hundred instructions.
constexpr int kMinContactsPerInitTask = 256;

/// CreateContact for the batches' kept pairs without the user's filter, in three passes whose
/// contacts, slots, serial numbers and lists are CreateContact's one pair after another: on
/// this thread, in order, the pairs with no contact yet take their slots (ContactShapes,
/// TakeContactSlot); on the threads, each new contact's own fields (InitContact; Read: the
/// shapes and bodies. Written: the contact); on this thread, in order, the links (LinkContact).
void MakeContacts(WorldState& world, int batches)
{
    std::vector<NewContact>& made = world.scratch.newContacts;
    made.clear();
    for (int b = 0; b < batches; ++b)
    {
        for (const ShapePair& pair : world.scratch.pairBatches[static_cast<std::size_t>(b)].kept)
        {
            std::int32_t sA;
            std::int32_t sB;
            if (!world.contactPairs.Contains(ShapePairKey(pair.shapeA, pair.shapeB)) &&
                ContactShapes(world, pair.shapeA, pair.shapeB, sA, sB))
            {
                made.push_back({TakeContactSlot(world, sA, sB), sA, sB});
            }
        }
    }
    const WorldState& read = world;
    ForEachIndex(world.Tasks(), static_cast<int>(made.size()), kMinContactsPerInitTask,
                 [&world, &read, &made](int i)
                 {
                     const NewContact& contact = made[static_cast<std::size_t>(i)];
                     InitContact(read, world.contacts[contact.index], contact.shapeA,
                                 contact.shapeB);
                 });
    for (const NewContact& contact : made)
    {
        LinkContact(world, contact.index);
    }
}

void CreateContact(WorldState& world, std::int32_t shapeIndexA, std::int32_t shapeIndexB)
{
    std::int32_t sA;
    std::int32_t sB;
    if (!ContactShapes(world, shapeIndexA, shapeIndexB, sA, sB))
    {
        return;
    }
    const std::int32_t index = TakeContactSlot(world, sA, sB);
    InitContact(world, world.contacts[index], sA, sB);
    LinkContact(world, index);
}

namespace
{

/// Box2D 2.4.1's b2ContactManager::AddPair.
void AddPair(WorldState& world, std::int32_t shapeIndexA, std::int32_t shapeIndexB)
{
    if (!BuiltInRulesRefuse(world, shapeIndexA, shapeIndexB))
    {
        CreateContact(world, shapeIndexA, shapeIndexB);
    }
}

} // namespace

void FindNewContacts(WorldState& world)
{
    if (!world.collision.threadedStages)
    {
        // One thread (Box2D's back end), the pairs added as b2BroadPhase adds them.
        world.broadPhase.UpdatePairs([&world](std::int32_t shapeA, std::int32_t shapeB)
                                     { AddPair(world, shapeA, shapeB); });
    }
    else
    {
        FindNewContactsInBatches(world);
    }
    world.newShapes = false;
}

void DestroyContact(WorldState& world, std::int32_t contactIndex)
{
    Contact& contact = world.contacts[contactIndex];
    if (contact.IsTouching())
    {
        RecordTouchEnded(world, contact);
    }
    if (contact.prev != kNullIndex)
    {
        world.contacts[contact.prev].next = contact.next;
    }
    if (contact.next != kNullIndex)
    {
        world.contacts[contact.next].prev = contact.prev;
    }
    if (world.contactList == contactIndex)
    {
        world.contactList = contact.next;
    }
    UnlinkEdge(world, world.bodies[contact.bodyA], contactIndex, 0);
    UnlinkEdge(world, world.bodies[contact.bodyB], contactIndex, 1);
    world.contactPairs.Erase(ShapePairKey(contact.shapeA, contact.shapeB));
    if ((contact.flags & Contact::Swept) != 0)
    {
        // The last swept contact takes its slot.
        const std::int32_t moved = world.sweptContacts.back();
        world.sweptContacts[static_cast<std::size_t>(contact.sweptSlot)] = moved;
        world.contacts[moved].sweptSlot = contact.sweptSlot;
        world.sweptContacts.pop_back();
        contact.sweptSlot = -1;
    }
    contact.alive = false;
    contact.flags = 0;
    world.freeContacts.push_back(contactIndex);
    --world.contactCount;
}

void WakeTouchingBodies(WorldState& world, std::int32_t bodyIndex, std::int32_t shapeIndex)
{
    for (std::int32_t key = world.bodies[bodyIndex].contactList; key != kNullIndex;)
    {
        const Contact& contact = world.contacts[EdgeOwner(key)];
        key = contact.edges[EdgeSide(key)].next;
        const bool ofShape =
            shapeIndex < 0 || contact.shapeA == shapeIndex || contact.shapeB == shapeIndex;
        // As b2Contact's destruction: a contact with manifold points wakes its bodies; a
        // sensor's overlap (no points) wakes nobody.
        if (ofShape && contact.IsTouching() && !contact.IsSensor())
        {
            WakeBody(world, contact.bodyA);
            WakeBody(world, contact.bodyB);
        }
    }
}

void FlagContactsForFiltering(WorldState& world, std::int32_t bodyA, std::int32_t bodyB)
{
    for (std::int32_t key = world.bodies[bodyB].contactList; key != kNullIndex;)
    {
        Contact& contact = world.contacts[EdgeOwner(key)];
        const Edge& edge = contact.edges[EdgeSide(key)];
        if (edge.other == bodyA)
        {
            contact.flags |= Contact::Filter;
        }
        key = edge.next;
    }
}

namespace
{

/// Contacts to a range of the threaded Collide's manifold pass: a manifold costs a few hundred
/// to a few thousand instructions, so 64 of them outweigh handing a range to another thread.
constexpr int kMinContactsPerTask = 64;

/// Recycling is the back end's choice (0: never, Box2D's), with or without a pre-solve
/// callback: a kept manifold is shown to the callback as a fresh one is (KeepContact), so that
/// installing a callback that enables every contact changes nothing (issue 36: turning
/// recycling off for it made the colour and soft-step trajectories differ from step 2).
Real RecycleDistance(const WorldState& world)
{
    return world.collision.recycleDistance;
}

/// Collide's choice for one contact from the activity test on: the part that a contact skipped
/// as asleep repeats when an earlier contact of the list woke one of its bodies. Inlined: calls
/// per contact cost the serial walk 13 % more instructions (large_pyramid by colour).
[[gnu::always_inline]] inline CollideAction DecideActive(const WorldState& world,
                                                         const Contact& contact,
                                                         Real recycleDistance)
{
    const Body& bodyA = world.bodies[contact.bodyA];
    const Body& bodyB = world.bodies[contact.bodyB];
    const bool activeA = bodyA.awake && bodyA.type != BodyType::Static;
    const bool activeB = bodyB.awake && bodyB.type != BodyType::Static;
    if (!activeA && !activeB)
    {
        return CollideAction::Asleep;
    }
    // Pairs whose fat boxes part are destroyed; the rest get a fresh manifold or keep theirs.
    const Shape& shapeA = world.shapes[contact.shapeA];
    const Shape& shapeB = world.shapes[contact.shapeB];
    if (!world.broadPhase.TestOverlap(shapeA.proxyId, shapeB.proxyId))
    {
        return CollideAction::Destroy;
    }
    // The flag first: it is never set in Box2D's back end, whose every contact comes here.
    if ((contact.flags & Contact::PoseKept) != 0 && recycleDistance > 0 &&
        KeepsManifold(recycleDistance, contact, shapeB, bodyA.xf, bodyB.xf))
    {
        return CollideAction::Keep;
    }
    return CollideAction::Update;
}

/// A contact flagged for filtering still collides? As b2ContactManager::Collide: the bodies,
/// then the filter (bits, then the user's); the flag is cleared when it does. Rare (a joint was
/// made or destroyed), so kept out of the walks' loops.
[[gnu::noinline]] bool Refilter(WorldState& world, Contact& contact)
{
    const Shape& shapeA = world.shapes[contact.shapeA];
    const Shape& shapeB = world.shapes[contact.shapeB];
    if (!BodiesShouldCollide(world, contact.bodyB, contact.bodyA) ||
        !FiltersAllow(shapeA.def.filter, shapeB.def.filter) ||
        !CustomFilterAllows(world, contact.shapeA, contact.shapeB))
    {
        return false;
    }
    contact.flags &= ~Contact::Filter;
    return true;
}

bool PassesFilter(WorldState& world, Contact& contact)
{
    return (contact.flags & Contact::Filter) == 0 || Refilter(world, contact);
}

/// Collide's choice for one contact: the filter first, then the rest.
[[gnu::always_inline]] inline CollideAction Decide(WorldState& world, Contact& contact,
                                                   Real recycleDistance)
{
    return PassesFilter(world, contact) ? DecideActive(world, contact, recycleDistance)
                                        : CollideAction::Destroy;
}

/// What UpdateContact would do to a contact that stays touching with the same manifold, without
/// a pre-solve callback: no events; the contact takes part again (Box2D: enabled).
void KeepManifold(Contact& contact)
{
    contact.flags &= ~Contact::Disabled;
}

/// The same with the pre-solve callback, if any, asked about the kept manifold as UpdateContact
/// asks about a fresh one.
void KeepContact(WorldState& world, std::int32_t contactIndex)
{
    Contact& contact = world.contacts[contactIndex];
    KeepManifold(contact);
    if (contact.IsTouching() && !contact.IsSensor() && world.preSolve)
    {
        RunPreSolve(world, contactIndex);
    }
}

/// Does Collide's `action` to contact `c` at once.
[[gnu::always_inline]] inline void Perform(WorldState& world, std::int32_t c, CollideAction action)
{
    switch (action)
    {
    case CollideAction::Destroy:
        DestroyContact(world, c);
        break;
    case CollideAction::Keep:
        KeepContact(world, c);
        break;
    case CollideAction::Update:
        UpdateContact(world, c);
        break;
    case CollideAction::Asleep:
    case CollideAction::Pending:
        break;
    }
}

/// UpdateContact's first half, which writes only the contact, so that contacts can be computed
/// on several threads at once: the manifold (a sensor's overlap) at the bodies' present poses,
/// and the pose it was computed at for recycling. Returns the new touching state.
[[gnu::always_inline]] inline bool ComputeContact(const WorldState& world, Contact& contact)
{
    const Shape& shapeA = world.shapes[contact.shapeA];
    const Shape& shapeB = world.shapes[contact.shapeB];
    const Transform& xfA = world.bodies[contact.bodyA].xf;
    const Transform& xfB = world.bodies[contact.bodyB].xf;
    const bool touching = contact.IsSensor()
                              ? UpdateSensorOverlap(contact, shapeA, xfA, shapeB, xfB)
                              : UpdateManifold(contact, shapeA, xfA, shapeB, xfB);
    if (world.collision.recycleDistance > 0 && !contact.IsSensor())
    {
        contact.keptPose = MulT(xfA, xfB);
        contact.flags |= Contact::PoseKept;
    }
    else
    {
        contact.flags &= ~Contact::PoseKept;
    }
    return touching;
}

/// UpdateContact's second half, which touches the rest of the world and so runs on the
/// stepping thread, in list order: wakes, the touching flag, begin/end events, pre-solve.
[[gnu::always_inline]] inline void ApplyContact(WorldState& world, std::int32_t contactIndex,
                                                bool touching)
{
    Contact& contact = world.contacts[contactIndex];
    contact.flags &= ~Contact::Disabled; // an updated contact takes part again (Box2D: enabled)
    const bool wasTouching = contact.IsTouching();
    if (!contact.IsSensor() && touching != wasTouching)
    {
        // A solid contact that begins or ends changes both bodies' islands: wake them
        // (b2Contact::Update; a sensor's overlap wakes nobody).
        WakeBody(world, contact.bodyA);
        WakeBody(world, contact.bodyB);
    }
    if (touching)
    {
        contact.flags |= Contact::Touching;
    }
    else
    {
        contact.flags &= ~Contact::Touching;
    }
    if (touching && !wasTouching)
    {
        RecordTouchBegan(world, contact);
    }
    else if (!touching && wasTouching)
    {
        RecordTouchEnded(world, contact);
    }
    if (touching && !contact.IsSensor() && world.preSolve)
    {
        RunPreSolve(world, contactIndex);
    }
}

/// Box2D 2.4.1's walk: each contact decided and done in turn.
void CollideSerial(WorldState& world)
{
    const Real recycleDistance = RecycleDistance(world);
    for (std::int32_t c = world.contactList; c != kNullIndex;)
    {
        const std::int32_t next = world.contacts[c].next; // c may be destroyed
        Perform(world, c, Decide(world, world.contacts[c], recycleDistance));
        c = next;
    }
}

/// The threaded Collide's list, in list order. Read: the contacts' list links only, so that it
/// runs beside DecideAndCompute, which writes the rest of the contacts. Written: `order`, sized
/// to the contact count before.
void ListContacts(const WorldState& world, std::vector<std::int32_t>& order)
{
    std::size_t i = 0;
    for (std::int32_t c = world.contactList; c != kNullIndex; c = world.contacts[c].next)
    {
        order[i++] = c;
    }
}

/// Decides a contact (not flagged for filtering) and computes or keeps its manifold, on the
/// threads. Read: the bodies, shapes and fat boxes, which nothing changes until
/// ApplyListedWork. Written: the contact (all but its list links) and its work. A fresh
/// manifold that leaves the touching state as it was is all done here (ApplyContact then only
/// clears Disabled: no wake, no event, and no pre-solve callback on the threads), and becomes
/// Keep, so that ApplyListedWork, on the calling thread, is left only the contacts that begin
/// or end touching, those destroyed, those found asleep and those flagged for filtering.
[[gnu::always_inline]] inline CollideWork DecideAndCompute(const WorldState& world,
                                                           Contact& contact, Real recycleDistance)
{
    CollideWork work{DecideActive(world, contact, recycleDistance), false};
    if (work.action == CollideAction::Keep)
    {
        KeepManifold(contact); // with a pre-solve callback, Collide is serial
    }
    else if (work.action == CollideAction::Update)
    {
        work.touching = ComputeContact(world, contact);
        if (work.touching == contact.IsTouching())
        {
            KeepManifold(contact); // ApplyContact's only change to it
            work.action = CollideAction::Keep;
        }
    }
    return work;
}

/// The last pass, in list order, so that filtering, wakes, events and their order are the
/// serial walk's. A contact found asleep on the threads is decided again here, where the
/// serial walk would have decided it: an earlier contact that began or ended touching may have
/// woken a body. A contact flagged for filtering is filtered, decided and done here, as the
/// serial walk does it (the user's filter is called on this thread, in list order).
void ApplyListedWork(WorldState& world, const std::vector<std::int32_t>& order,
                     const std::vector<CollideWork>& work)
{
    const Real recycleDistance = RecycleDistance(world);
    for (const std::int32_t c : order)
    {
        const CollideWork& done = work[static_cast<std::size_t>(c)];
        switch (done.action)
        {
        case CollideAction::Update:
            ApplyContact(world, c, done.touching);
            break;
        case CollideAction::Asleep:
            Perform(world, c, DecideActive(world, world.contacts[c], recycleDistance));
            break;
        case CollideAction::Destroy:
            DestroyContact(world, c);
            break;
        case CollideAction::Pending:
            Perform(world, c, Decide(world, world.contacts[c], recycleDistance));
            break;
        case CollideAction::Keep: // done on the threads
            break;
        }
    }
}

/// The manifolds go to the threads only where nothing else can notice: never for Box2D's back
/// end (single-threaded, bit for bit Box2D 2.4.1), nor with a pre-solve callback (the user's
/// code, called in list order on the stepping thread, between the manifolds).
bool CollidesOnThreads(const WorldState& world)
{
    return world.StageTasks() != nullptr && !world.preSolve;
}

} // namespace

void Collide(WorldState& world)
{
    if (!CollidesOnThreads(world))
    {
        CollideSerial(world);
        return;
    }
    // On the threads, by contact index, every alive contact not flagged for filtering decided
    // and its manifold computed or kept (DecideAndCompute), and beside them the list walked
    // (ListContacts); then on this thread, in list order, the rest (ApplyListedWork).
    StepScratch& scratch = world.scratch;
    scratch.collideOrder.resize(static_cast<std::size_t>(world.contactCount));
    scratch.collideWork.resize(world.contacts.size());
    const Real recycleDistance = RecycleDistance(world);
    ForRangesBeside(
        world.Tasks(), static_cast<int>(world.contacts.size()), kMinContactsPerTask,
        [&world, &scratch] { ListContacts(world, scratch.collideOrder); },
        [&world, &scratch, recycleDistance](int begin, int end, int)
        {
            for (int c = begin; c < end; ++c)
            {
                Contact& contact = world.contacts[static_cast<std::size_t>(c)];
                if (!contact.alive)
                {
                    continue;
                }
                CollideWork& work = scratch.collideWork[static_cast<std::size_t>(c)];
                work = (contact.flags & Contact::Filter) != 0
                           ? CollideWork{CollideAction::Pending, false}
                           : DecideAndCompute(world, contact, recycleDistance);
            }
        });
    ApplyListedWork(world, scratch.collideOrder, scratch.collideWork);
}

void UpdateContact(WorldState& world, std::int32_t contactIndex)
{
    ApplyContact(world, contactIndex, ComputeContact(world, world.contacts[contactIndex]));
}

} // namespace meff::detail
