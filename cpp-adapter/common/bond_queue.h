// Intact bonds of a force pass, queued for the core: the same in the LIGGGHTS
// and the LAMMPS adapter. A queue holds up to `Block` bonds of one bond model,
// each as its two atom indices, where its state lives and what the adapter
// keeps for applying its loads afterwards (`Pending`). One
// granbond_bond_compute_indexed call advances them, several per
// instruction, reading positions, velocities and spins from the engine's
// atom arrays; a block is small enough to stay in cache between queueing
// and applying.
#ifndef GRANBOND_BOND_QUEUE_H
#define GRANBOND_BOND_QUEUE_H

#include "granbond.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace granbond {

template<class Pending, size_t Block>
struct BondQueue {
    const GbBondModel *model;
    size_t count;
    std::vector<Pending> bonds;
    std::vector<int32_t> pairs;   // i, j per bond
    std::vector<double *> states;
    std::vector<GbBondOutput> outputs;

    explicit BondQueue(const GbBondModel *m) :
        model(m), count(0), bonds(Block), pairs(2 * Block), states(Block), outputs(Block)
    {}

    // Queues the bond of atoms i and j with its state at `state`; the
    // caller fills in the returned record.
    Pending &push(int i, int j, double *state)
    {
        pairs[2 * count] = i;
        pairs[2 * count + 1] = j;
        states[count] = state;
        return bonds[count++];
    }
    bool full() const { return count == Block; }

    // Advances the `count` queued bonds from the arrays of `atom` (LAMMPS'
    // and LIGGGHTS' Atom: x, v and omega are blocks of 3 doubles per atom,
    // as memory->create makes them; local and ghost atoms); on failure
    // `bad` is the bond's position in the queue.
    template<class Atom>
    GbStatus advance(const Atom *atom, double dt, size_t &bad)
    {
        GbAtomArrays arrays;
        arrays.x = atom->x[0];
        arrays.v = atom->v[0];
        arrays.omega = atom->omega[0];
        arrays.radius = atom->radius;
        arrays.count = static_cast<size_t>(atom->nlocal + atom->nghost);
        bad = 0;
        const GbStatus status = granbond_bond_compute_indexed(model, count, &arrays, pairs.data(), dt,
                                                              states.data(), outputs.data(), &bad);
        if (bad >= count) bad = 0;
        return status;
    }
};

// The queue of `model` in `queues`, made on first use; `last` is where the
// previous lookup ended (a pass usually meets one bond model). The search is
// kept out of line so that the common case inlines into the pair loop.
template<class Queue>
__attribute__((noinline)) Queue &findQueue(std::vector<Queue> &queues, const GbBondModel *model, size_t &last)
{
    for (last = 0; last < queues.size(); last++)
        if (queues[last].model == model) return queues[last];
    queues.push_back(Queue(model));
    return queues.back();
}

template<class Queue>
inline Queue &queueOf(std::vector<Queue> &queues, const GbBondModel *model, size_t &last)
{
    if (last < queues.size() && queues[last].model == model) return queues[last];
    return findQueue(queues, model, last);
}

}

#endif
