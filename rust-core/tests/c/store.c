/*
 * The bond store from C: a bond created, stepped, moved to another store
 * with its atom, broken, counted.
 */

#include "harness.h"

/* Two atoms (ids 11 and 4) at the fixture's pair positions, both local. */
typedef struct {
    int32_t ids[2];
    double x[6], v[6], omega[6], radius[2];
    int32_t types[2];
} TwoAtoms;

static void two_atoms(TwoAtoms *a, double r)
{
    GbPairKinematics k;
    int c;
    pair_at(&k, r, R_I, R_J);
    memset(a, 0, sizeof *a);
    a->ids[0] = 11;
    a->ids[1] = 4;
    for (c = 0; c < 3; c++) {
        a->x[c] = k.x_i[c];
        a->x[3 + c] = k.x_j[c];
    }
    a->v[0] = 1.0e-3;
    a->omega[5] = 2.0;
    a->radius[0] = R_I;
    a->radius[1] = R_J;
    a->types[0] = a->types[1] = 1;
}

static GbStoreAtoms store_atoms(const TwoAtoms *a)
{
    GbStoreAtoms s;
    s.ids.narrow = a->ids;
    s.ids.wide = NULL;
    s.ids.count = 2;
    s.nlocal = 2;
    s.x = a->x;
    s.types = a->types;
    s.reach = 0.0;
    return s;
}

static GbAtomArrays atom_arrays(const TwoAtoms *a)
{
    GbAtomArrays s;
    s.x = a->x;
    s.v = a->v;
    s.omega = a->omega;
    s.radius = a->radius;
    s.count = 2;
    return s;
}

static GbPairKinematics kinematics(const TwoAtoms *a, int i, int j)
{
    GbPairKinematics k;
    int c;
    for (c = 0; c < 3; c++) {
        k.x_i[c] = a->x[3 * i + c];
        k.x_j[c] = a->x[3 * j + c];
        k.v_i[c] = a->v[3 * i + c];
        k.v_j[c] = a->v[3 * j + c];
        k.w_i[c] = a->omega[3 * i + c];
        k.w_j[c] = a->omega[3 * j + c];
    }
    k.radius_i = a->radius[i];
    k.radius_j = a->radius[j];
    return k;
}

int test_bond_store(void)
{
    const GbBondParams p = bond_fixture();
    const int32_t kinds[4] = {-1, -1, -1, 0};
    GbBondModel *m = NULL;
    GbBondStore *store = NULL, *other = NULL;
    const GbBondModel *models[1];
    TwoAtoms a;
    GbStoreAtoms sa;
    GbAtomArrays arrays;
    GbAtomIds ids;
    GbLinkReport report;
    GbStoreCounts counts;
    GbBrokenBond broken;
    GbPairKinematics k;
    GbBondOutput outs[GRANBOND_BOND_STORE_CHUNK], want;
    int32_t ends[2 * GRANBOND_BOND_STORE_CHUNK], owner = -2, created = 0, bond_ends[2];
    double state[GRANBOND_BOND_STATE_LEN], buf[64], force[6] = {0}, torque[6] = {0};
    GbAtomLoads loads;
    size_t count = 99, written = 0, read = 0;
    int64_t partner = 0;

    if (new_bond_model(&p, &m))
        return 1;
    models[0] = m;
    two_atoms(&a, R0_NOMINAL);
    sa = store_atoms(&a);
    arrays = atom_arrays(&a);
    ids = sa.ids;
    EXPECT_OK(granbond_bond_store_new(&store), "granbond_bond_store_new");
    EXPECT_OK(granbond_bond_store_grow(store, 2), "granbond_bond_store_grow");
    EXPECT_OK(granbond_bond_store_link(store, &sa, kinds, 1, &report), "granbond_bond_store_link, no bond yet");
    CHECK(report.linked == 0, "an empty store links nothing");
    CHECK(granbond_bond_store_seen(store, 1) == 4, "a link marks the local atoms seen");

    /* The owner of the pair: the smaller id, atom 1 (id 4). */
    owner = granbond_bond_store_creates_here(1, 1, 11, 4, 0);
    CHECK(owner == 1, "both local: the smaller id owns the bond");
    CHECK(granbond_bond_store_creates_here(1, 0, 11, 4, 1) == -1, "newton off: the rank of the smaller id creates");

    EXPECT_OK(granbond_bond_store_begin_pass(store, DT, 1, 0), "granbond_bond_store_begin_pass");
    k = kinematics(&a, 1, 0);
    EXPECT_OK(granbond_bond_store_try_create(store, m, 0, 1, 0, 4, 11, &k, CREATE_STEP, &created),
              "granbond_bond_store_try_create");
    CHECK(created == 1, "created at the creation step");
    loads.force = force;
    loads.torque = torque;
    loads.count = 2;
    loads.nlocal = 2;
    loads.ghost_rows = NULL;
    loads.relax = NULL;
    EXPECT_OK(granbond_bond_store_step_next(store, models, 1, &arrays, &ids, &loads, ends, outs, &count, NULL),
              "granbond_bond_store_step_next");
    CHECK(count == 1 && ends[0] == 1 && ends[1] == 0, "the new bond stepped in its pass, owner first");
    CHECK(vec_equal(force + 3, outs[0].force_i) && vec_equal(torque + 3, outs[0].torque_i) &&
              vec_equal(torque, outs[0].torque_j) && force[0] == -outs[0].force_i[0],
          "the loads added to the atoms: the owner's, the partner's (minus the force)");
    /* the same step from C on a copy of a fresh bond */
    if (create_bond(m, state))
        return 1;
    state[1] = R0_NOMINAL; /* r0 */
    EXPECT_OK(granbond_bond_compute(m, &k, DT, state, &want), "granbond_bond_compute");
    CHECK(vec_equal(outs[0].force_i, want.force_i) && vec_equal(outs[0].torque_j, want.torque_j),
          "the store's step is the bond's step");
    EXPECT(granbond_bond_store_step_rest(store, models, 1, &arrays, &ids, NULL, &count, NULL), GB_STATUS_NULL_POINTER,
           "granbond_bond_store_step_rest, no loads");
    loads.torque = force + 3;
    EXPECT(granbond_bond_store_step_rest(store, models, 1, &arrays, &ids, &loads, &count, NULL),
           GB_STATUS_INVALID_ARGUMENT, "granbond_bond_store_step_rest, torques over the forces");
    loads.torque = torque;
    loads.count = 1;
    loads.nlocal = 1;
    EXPECT(granbond_bond_store_step_rest(store, models, 1, &arrays, &ids, &loads, &count, NULL),
           GB_STATUS_INVALID_ARGUMENT, "granbond_bond_store_step_rest, sums for fewer atoms than the arrays");
    loads.count = 2;
    loads.nlocal = 2;
    EXPECT_OK(granbond_bond_store_step_rest(store, models, 1, &arrays, &ids, &loads, &count, NULL),
              "granbond_bond_store_step_rest, nothing left");
    CHECK(count == 0, "every bond stepped once");
    CHECK(granbond_bond_store_broken_count(store) == 0, "nothing broke");
    EXPECT_OK(granbond_bond_store_finish_pass(store), "granbond_bond_store_finish_pass");
    CHECK(granbond_bond_store_len(store) == 1 && granbond_bond_store_bytes(store) > 0, "one bond held");
    EXPECT_OK(granbond_bond_store_bond(store, 0, bond_ends, &partner, state), "granbond_bond_store_bond");
    CHECK(partner == 11 && bond_ends[0] == 1 && state[0] > 0.0, "the bond: partner id 11, intact (a positive rest length)");
    {
        double keys[2] = {0.0, 0.0};
        size_t nkeys = 0;
        GbCheckReport found;
        EXPECT_OK(granbond_bond_store_check_keys(store, &ids, sa.nlocal, keys, 2, &nkeys, &found),
                  "granbond_bond_store_check_keys");
        CHECK(nkeys == 1 && found.level == 0 && keys[0] < keys[1] && keys[1] == 11.0,
              say("the bond's key: its atoms' ids, the lower first (%g %g)", keys[0], keys[1]));
        EXPECT_OK(granbond_bond_store_check_keys(store, &ids, 0, keys, 2, &nkeys, &found),
                  "granbond_bond_store_check_keys, no local atom");
        CHECK(nkeys == 0 && found.level == 1 && strstr(found.message, "does not join its owner"),
              say("a bond whose owner is not local is found: %s", found.message));
        EXPECT_OK(granbond_bond_store_check_flag(store, 1, 0, &ids, 1, &found), "granbond_bond_store_check_flag");
        CHECK(found.level == 0, "the bonded pair flagged: nothing to say");
        EXPECT_OK(granbond_bond_store_check_flag(store, 1, 0, &ids, 0, &found),
                  "granbond_bond_store_check_flag, not flagged");
        CHECK(found.level == 1 && strstr(found.message, "is bonded, but not flagged"),
              say("a bonded pair without its flag is found: %s", found.message));
        EXPECT(granbond_bond_store_check_flag(store, 1, 5, &ids, 1, &found), GB_STATUS_INVALID_ARGUMENT,
               "granbond_bond_store_check_flag, j beyond the atoms");
    }
    {
        double energy = -1.0;
        EXPECT_OK(granbond_bond_store_stored_energy(store, models, 1, &arrays, &energy),
                  "granbond_bond_store_stored_energy");
        CHECK(energy >= 0.0 && energy < 1e-6, "a bond near its rest length stores little energy");
        /* a bond's energies: kept per bond only while asked for */
        {
            double e[3] = {-1.0, -1.0, -1.0};
            EXPECT(granbond_bond_store_bond_energy(store, models, 1, &arrays, 0, e), GB_STATUS_INVALID_ARGUMENT,
                   "granbond_bond_store_bond_energy, not kept");
            EXPECT_OK(granbond_bond_store_keep_energy_budget(store, 1, 1), "granbond_bond_store_keep_energy_budget");
            EXPECT_OK(granbond_bond_store_bond_energy(store, models, 1, &arrays, 0, e),
                      "granbond_bond_store_bond_energy");
            CHECK(e[0] == energy && e[1] == 0.0 && e[2] == 0.0, "its stored energy, nothing dissipated yet");
            CHECK(granbond_bond_energy_field_count() == 3, "three energy fields");
            {
                /* the atoms' shares of the damping loads: none kept before a force pass */
                double table[2 * 7] = {0};
                EXPECT(granbond_bond_store_add_dissipated_shares(store, models, 1, table, 2, 7, 2),
                       GB_STATUS_INVALID_ARGUMENT, "granbond_bond_store_add_dissipated_shares, a share beyond the row");
                EXPECT_OK(granbond_bond_store_add_dissipated_shares(store, models, 1, table, 2, 7, 1),
                          "granbond_bond_store_add_dissipated_shares");
                CHECK(table[1] == 0.0 && table[8] == 0.0, "no damping loads yet: nothing added");
            }
            EXPECT_OK(granbond_bond_store_keep_energy_budget(store, 0, 0), "granbond_bond_store_keep_energy_budget, off");
            {
                double table[7] = {0};
                EXPECT(granbond_bond_store_add_dissipated_shares(store, models, 1, table, 1, 7, 1),
                       GB_STATUS_INVALID_ARGUMENT, "granbond_bond_store_add_dissipated_shares, no budget kept");
            }
        }
    }

    /* The view: the rows another rank's ghosts of these atoms would get. */
    {
        double row[8];
        size_t width = granbond_bond_store_view_width(store);
        int32_t creates = -1;
        CHECK(width == 2, "a view row: the count and one partner");
        EXPECT(granbond_bond_store_pack_view(store, 1, row, 1), GB_STATUS_INVALID_ARGUMENT,
               "granbond_bond_store_pack_view, a row too narrow");
        EXPECT_OK(granbond_bond_store_pack_view(store, 1, row, width), "granbond_bond_store_pack_view");
        CHECK(row[0] == 1.0 && row[1] == 11.0, "atom 1 owns a bond to id 11");
        EXPECT_OK(granbond_bond_store_clear_view(store), "granbond_bond_store_clear_view");
        EXPECT_OK(granbond_bond_store_unpack_view(store, 1, row, width, &ids, 2), "granbond_bond_store_unpack_view");
        EXPECT_OK(granbond_bond_store_finish_view(store), "granbond_bond_store_finish_view");
        CHECK(granbond_bond_store_bonded(store, 0, 1, &ids) == 1 && granbond_bond_store_bonded(store, 1, 0, &ids) == 1,
              "the pair is bonded, seen from either atom");
        EXPECT_OK(granbond_bond_store_would_create(store, m, 0, 1, &k, CREATE_STEP, &creates),
                  "granbond_bond_store_would_create");
        CHECK(creates == 1, "the creation rules hold for the pair at the creation step");
        {
            uint32_t counts[2] = {9, 9};
            EXPECT_OK(granbond_bond_store_count_atoms(store, counts, 2, &ids), "granbond_bond_store_count_atoms");
            CHECK(counts[0] == 1 && counts[1] == 1, "one bond on each atom, though the view holds it too");
        }
    }

    /* Atom 1 migrates to another store, with its bond. */
    CHECK(granbond_bond_store_packed_len(store, 1) == 2 + 1 + GRANBOND_BOND_STATE_LEN &&
              granbond_bond_store_most_packed_len(store) >= granbond_bond_store_packed_len(store, 1),
          "packed length: seen id, count, partner id and state");
    EXPECT(granbond_bond_store_pack(store, 1, 1, buf, 3, &written), GB_STATUS_INVALID_ARGUMENT,
           "granbond_bond_store_pack, buffer too short");
    EXPECT_MESSAGE("capacity");
    EXPECT_OK(granbond_bond_store_pack(store, 1, 1, buf, 64, &written), "granbond_bond_store_pack, leaving");
    {
        size_t len = 0;
        EXPECT_OK(granbond_bond_store_packed_len_in(buf, 2, &len), "granbond_bond_store_packed_len_in");
        CHECK(len == written, "the head of the packed bonds says their length");
    }
    EXPECT_OK(granbond_bond_store_new(&other), "granbond_bond_store_new");
    EXPECT_OK(granbond_bond_store_grow(other, 2), "granbond_bond_store_grow");
    EXPECT_OK(granbond_bond_store_unpack(other, 1, buf, written, &read), "granbond_bond_store_unpack");
    CHECK(read == written, "everything packed is read");
    EXPECT(granbond_bond_store_unpack(other, 0, buf, 2, &read), GB_STATUS_INVALID_ARGUMENT,
           "granbond_bond_store_unpack, a short buffer");
    EXPECT_OK(granbond_bond_store_link(store, &sa, kinds, 1, &report), "granbond_bond_store_link, after leaving");
    CHECK(report.linked == 0 && report.owner_gone == 0, "a bond that left is no loss");
    /* its partner, seen by the rank that owns it */
    EXPECT_OK(granbond_bond_store_set_seen(other, 0, 11), "granbond_bond_store_set_seen");
    EXPECT_OK(granbond_bond_store_link(other, &sa, kinds, 1, &report), "granbond_bond_store_link, arrived");
    CHECK(report.linked == 1, "the bond arrived with its atom");

    /* Stretched past max_distance: broken, counted, gone. */
    a.x[0] += (MAX_DISTANCE - R0_NOMINAL) * 2.0 * AXIS[0] * 10.0;
    a.x[1] += (MAX_DISTANCE - R0_NOMINAL) * 2.0 * AXIS[1] * 10.0;
    a.x[2] += (MAX_DISTANCE - R0_NOMINAL) * 2.0 * AXIS[2] * 10.0;
    EXPECT_OK(granbond_bond_store_keep_energy_budget(other, 1, 0), "granbond_bond_store_keep_energy_budget");
    EXPECT_OK(granbond_bond_store_begin_pass(other, DT, 1, 0), "granbond_bond_store_begin_pass");
    EXPECT_OK(granbond_bond_store_step_next(other, models, 1, &arrays, &ids, NULL, ends, outs, &count, NULL),
              "granbond_bond_store_step_next, stretched");
    CHECK(count == 1 && vec_zero(outs[0].force_i), "a broken bond carries no load");
    CHECK(granbond_bond_store_broken_count(other) == 1, "one bond broke");
    EXPECT_OK(granbond_bond_store_broken(other, 0, &broken), "granbond_bond_store_broken");
    CHECK(broken.ids[0] == 4 && broken.ids[1] == 11 && broken.out.break_mode == GB_BREAK_MODE_DISTANCE,
          "the broken bond's ids and mode");
    EXPECT(granbond_bond_store_broken(other, 1, &broken), GB_STATUS_INVALID_ARGUMENT,
           "granbond_bond_store_broken, beyond the broken");
    /* a clump's pair bonds whatever the step, but not in the pass its bond broke in */
    k = kinematics(&a, 1, 0);
    created = -1;
    EXPECT_OK(granbond_bond_store_create_now(other, m, 0, 1, 0, 4, 11, &k, &created),
              "granbond_bond_store_create_now");
    CHECK(created == 0, "no bond forms again in the pass it broke in");
    EXPECT_NULL_ARG(granbond_bond_store_create_now(other, m, 0, 1, 0, 4, 11, NULL, &created),
                    "granbond_bond_store_create_now", "kinematics");
    EXPECT_OK(granbond_bond_store_finish_pass(other), "granbond_bond_store_finish_pass");
    EXPECT_OK(granbond_bond_store_counts(other, &counts), "granbond_bond_store_counts");
    CHECK(counts.broken_distance == 1 && counts.intact == 0, "counted broken by distance");
    counts.created = 5;
    EXPECT_OK(granbond_bond_store_restore_counts(other, &counts), "granbond_bond_store_restore_counts");
    EXPECT_OK(granbond_bond_store_counts(other, &counts), "granbond_bond_store_counts");
    CHECK(counts.created == 5, "counts restored");
    {
        GbEnergySums sums;
        EXPECT_OK(granbond_bond_store_energy_sums(other, &sums), "granbond_bond_store_energy_sums");
        CHECK(sums.released > 0.0 && sums.hysteresis == 0.0, "the broken bond released what it stored");
        sums.damping = 3.0;
        EXPECT_OK(granbond_bond_store_restore_energy_sums(other, &sums), "granbond_bond_store_restore_energy_sums");
        EXPECT_OK(granbond_bond_store_energy_sums(other, &sums), "granbond_bond_store_energy_sums");
        CHECK(sums.damping == 3.0, "energy sums restored");
    }

    /* Per-atom events. */
    EXPECT_OK(granbond_bond_store_set_seen(other, 0, 77), "granbond_bond_store_set_seen");
    EXPECT_OK(granbond_bond_store_copy(other, 0, 1), "granbond_bond_store_copy");
    CHECK(granbond_bond_store_seen(other, 1) == 77, "a copied atom keeps its seen id");
    EXPECT_OK(granbond_bond_store_clear(other, 1), "granbond_bond_store_clear");
    CHECK(granbond_bond_store_seen(other, 1) == 0, "a created atom was never seen");

    EXPECT_NULL_ARG(granbond_bond_store_new(NULL), "granbond_bond_store_new", "store");
    EXPECT_NULL_ARG(granbond_bond_store_link(store, NULL, kinds, 1, &report), "granbond_bond_store_link", "atoms");
    granbond_bond_store_free(store);
    granbond_bond_store_free(other);
    granbond_bond_store_free(NULL);
    granbond_bond_model_free(m);
    return 0;
}

/* A store whose bonds a topology lists (bond_style granbond): the listed
 * bond is created at rest at its length, kept while listed, lost when the
 * list drops it; a malformed entry is refused naming it. */
int test_bond_store_listed(void)
{
    GbBondStore *store = NULL;
    TwoAtoms a;
    GbStoreAtoms sa;
    GbLinkReport report;
    GbStoreCounts counts;
    GbListedBond listed = {0, 1, 0}, bad = {5, 1, 0};
    int32_t bond_ends[2];
    int64_t partner = 0;
    double state[GRANBOND_BOND_STATE_LEN];

    two_atoms(&a, R0_NOMINAL);
    sa = store_atoms(&a);
    EXPECT_OK(granbond_bond_store_new(&store), "granbond_bond_store_new");
    EXPECT_OK(granbond_bond_store_link_listed(store, &sa.ids, 2, sa.x, &listed, 1, &report),
              "granbond_bond_store_link_listed");
    CHECK(report.linked == 1 && granbond_bond_store_len(store) == 1, "the listed bond is held");
    EXPECT_OK(granbond_bond_store_bond(store, 0, bond_ends, &partner, state), "granbond_bond_store_bond");
    CHECK(bond_ends[0] == 0 && bond_ends[1] == 1 && partner == 4, "owner and partner as listed");
    EXPECT_OK(granbond_bond_store_link_listed(store, &sa.ids, 2, sa.x, NULL, 0, &report),
              "granbond_bond_store_link_listed, nothing listed");
    CHECK(report.linked == 0 && report.no_model == 1, "a bond the list drops is lost");
    EXPECT_OK(granbond_bond_store_counts(store, &counts), "granbond_bond_store_counts");
    CHECK(counts.created == 1 && counts.lost_no_model == 1 && counts.intact == 0, "created = lost");
    EXPECT(granbond_bond_store_link_listed(store, &sa.ids, 2, sa.x, &bad, 1, &report), GB_STATUS_INVALID_ARGUMENT,
           "an owner beyond the local atoms");
    EXPECT_MESSAGE("listed bond 0");
    EXPECT(granbond_bond_store_link_listed(NULL, &sa.ids, 2, sa.x, &listed, 1, &report), GB_STATUS_NULL_POINTER,
           "a null store");
    granbond_bond_store_free(store);
    return 0;
}
