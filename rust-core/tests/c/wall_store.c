/*
 * Wall bonds owned by their spheres, from C: a sphere on the edge of two
 * triangles meets one bond; the bond goes to another store with its sphere
 * and acts there the same; a sphere that left the system loses it, counted.
 */

#include "harness.h"

#define R_S 0.9e-3

static GbWallContact wall_contact(int64_t element, int64_t step, int32_t kind)
{
    GbWallContact c;
    memset(&c, 0, sizeof c);
    c.atom = 0;
    c.id = 42;
    c.wall = 0;
    c.element = element;
    c.step = step;
    c.pass = 2 * step + (kind == GB_WALL_PASS_SETUP);
    c.kind = kind;
    c.dt = 1.0e-6;
    c.may_create = kind == GB_WALL_PASS_FORCE;
    c.sphere.x[0] = 1.0e-3;
    c.sphere.x[1] = 1.0e-3;
    c.sphere.x[2] = R_S + 1.0e-6 * (double)(step - CREATE_STEP);
    c.sphere.radius = R_S;
    c.wall_velocity[2] = -0.01;
    c.contact_point[0] = c.sphere.x[0];
    c.contact_point[1] = c.sphere.x[1];
    return c;
}

int test_wall_store(void)
{
    const GbBondParams p = bond_fixture();
    GbBondModel *m = NULL;
    GbWallStore *store = NULL, *other = NULL;
    GbWallContact c;
    GbWallVisit v, w;
    GbStoreCounts counts;
    GbAtomIds ids;
    double buf[256];
    size_t written = 0, read = 0, len = 0;
    int64_t step, id_list[2] = {5, 42};
    int32_t acted;

    if (new_bond_model(&p, &m))
        return 1;
    EXPECT_OK(granbond_wall_store_new(&store), "granbond_wall_store_new");
    EXPECT_OK(granbond_wall_store_grow(store, 2), "granbond_wall_store_grow");

    /* Two triangles report the sphere in every force pass: one bond acts. */
    for (step = CREATE_STEP; step < CREATE_STEP + 5; step++) {
        acted = 0;
        c = wall_contact(1, step, GB_WALL_PASS_FORCE);
        EXPECT_OK(granbond_wall_store_visit(store, m, &c, &v), "granbond_wall_store_visit, first triangle");
        acted += v.act == GB_WALL_ACT_BOND;
        c = wall_contact(2, step, GB_WALL_PASS_FORCE);
        EXPECT_OK(granbond_wall_store_visit(store, m, &c, &w), "granbond_wall_store_visit, second triangle");
        CHECK(w.act == GB_WALL_ACT_HELD, "the other triangle holds the sphere");
        CHECK(acted == 1 && v.out.status == GB_BOND_STATUS_INTACT, "the bond acts at one triangle");
    }
    CHECK(v.out.force_i[2] < 0.0, "the sphere lifted off the wall is pulled back");
    EXPECT_OK(granbond_wall_store_counts(store, &counts), "granbond_wall_store_counts");
    CHECK(counts.created == 1 && counts.intact == 1, "one bond created, one intact");

    /* The sphere migrates to another store and acts there as here. */
    EXPECT_OK(granbond_wall_store_new(&other), "granbond_wall_store_new");
    EXPECT_OK(granbond_wall_store_grow(other, 1), "granbond_wall_store_grow");
    CHECK(granbond_wall_store_packed_len(store, 42) == granbond_wall_store_most_packed_len(store) &&
              granbond_wall_store_packed_len(store, 42) <= sizeof buf / sizeof buf[0],
          "packed length of the sphere's bonds");
    EXPECT_OK(granbond_wall_store_pack(store, 0, 42, 1, buf, sizeof buf / sizeof buf[0], &written),
              "granbond_wall_store_pack");
    EXPECT_OK(granbond_wall_store_packed_len_in(buf, 2, &len), "granbond_wall_store_packed_len_in");
    CHECK(len == written, "the packed head says its length");
    EXPECT_OK(granbond_wall_store_unpack(other, 0, 42, step - 1, buf, len, &read), "granbond_wall_store_unpack");
    CHECK(read == written, "the row read whole");
    c = wall_contact(2, step, GB_WALL_PASS_FORCE);
    EXPECT_OK(granbond_wall_store_visit(other, m, &c, &v), "granbond_wall_store_visit, after migration");
    CHECK(v.act == GB_WALL_ACT_BOND, "the bond acts on the other rank");
    EXPECT_OK(granbond_wall_store_counts(store, &counts), "granbond_wall_store_counts");
    CHECK(counts.intact == 0 && counts.created == 1, "the first store holds no bond, and counted its creation");

    /* A restart deck lists the walls the other way round: the bond moves
       from wall 0 to wall 1; a numbering without its wall is refused. */
    {
        const int64_t swapped[2] = {1, 0}, gone[2] = {-1, 0};
        EXPECT_OK(granbond_wall_store_renumber(other, swapped, 2), "granbond_wall_store_renumber");
        c = wall_contact(3, step + 1, GB_WALL_PASS_FORCE);
        c.wall = 1;
        EXPECT_OK(granbond_wall_store_visit(other, m, &c, &v), "granbond_wall_store_visit, renumbered wall");
        CHECK(v.act == GB_WALL_ACT_BOND, "the bond acts on its wall's new number");
        EXPECT(granbond_wall_store_renumber(other, gone, 1), GB_STATUS_INVALID_ARGUMENT,
               "granbond_wall_store_renumber, the bond's wall without a place");
        EXPECT_NULL_ARG(granbond_wall_store_renumber(other, NULL, 2), "granbond_wall_store_renumber", "map");
        /* the recount's keys: the one bond, by sphere and wall, held by
           the rank of its sphere */
        int64_t here[1] = {42}, elsewhere[1] = {43};
        GbAtomIds local;
        double keys[2] = {0.0, 0.0};
        size_t nkeys = 0;
        GbCheckReport found;
        local.narrow = NULL;
        local.wide = here;
        local.count = 1;
        CHECK(granbond_wall_store_len(other) == 1 && granbond_wall_store_len(NULL) == 0, "granbond_wall_store_len");
        EXPECT_OK(granbond_wall_store_check_keys(other, &local, keys, 2, &nkeys, &found),
                  "granbond_wall_store_check_keys");
        CHECK(nkeys == 1 && found.level == 0 && keys[0] == 42.0 && keys[1] == 1.0,
              "the bond's key: sphere 42 on wall 1");
        EXPECT(granbond_wall_store_check_keys(other, &local, keys, 0, &nkeys, &found), GB_STATUS_INVALID_ARGUMENT,
               "granbond_wall_store_check_keys, no room");
        local.wide = elsewhere;
        EXPECT_OK(granbond_wall_store_check_keys(other, &local, keys, 2, &nkeys, &found),
                  "granbond_wall_store_check_keys, the sphere elsewhere");
        CHECK(nkeys == 0 && found.level == 1 && strstr(found.message, "held by a rank without the sphere"),
              say("a bond held without its sphere is found: %s", found.message));
    }
    EXPECT_OK(granbond_wall_store_restore_counts(other, &counts), "granbond_wall_store_restore_counts");

    /* Atoms sorted (the sphere moves to slot 1), then the sphere gone. */
    EXPECT_OK(granbond_wall_store_grow(other, 2), "granbond_wall_store_grow");
    EXPECT_OK(granbond_wall_store_copy(other, 0, 1), "granbond_wall_store_copy");
    EXPECT_OK(granbond_wall_store_clear(other, 0), "granbond_wall_store_clear");
    ids.narrow = NULL;
    ids.wide = id_list;
    ids.count = 2;
    EXPECT_OK(granbond_wall_store_link(other, &ids), "granbond_wall_store_link, sphere at slot 1");
    EXPECT_OK(granbond_wall_store_counts(other, &counts), "granbond_wall_store_counts");
    CHECK(counts.intact == 1 && counts.lost_owner_gone == 0, "a sorted sphere keeps its bond");
    ids.count = 1;
    EXPECT_OK(granbond_wall_store_link(other, &ids), "granbond_wall_store_link, sphere gone");
    EXPECT_OK(granbond_wall_store_counts(other, &counts), "granbond_wall_store_counts");
    CHECK(counts.intact == 0 && counts.lost_owner_gone == 1 && counts.created == 1,
          "created = broken + intact + lost: the bond lost with its sphere");
    CHECK(granbond_wall_store_bytes(other) > 0, "granbond_wall_store_bytes");
    EXPECT_OK(granbond_wall_store_clear_all(other), "granbond_wall_store_clear_all");
    EXPECT_OK(granbond_wall_store_counts(other, &counts), "granbond_wall_store_counts");
    CHECK(counts.created == 0 && counts.lost_owner_gone == 0, "clear_all zeroes the counts");

    /* Refused: a pass kind that is none, a row of another layout, nulls. */
    c = wall_contact(1, step, 7);
    EXPECT(granbond_wall_store_visit(store, m, &c, &v), GB_STATUS_INVALID_ARGUMENT, "granbond_wall_store_visit, kind 7");
    buf[1] += 1.0;
    EXPECT(granbond_wall_store_packed_len_in(buf, 2, &len), GB_STATUS_INVALID_ARGUMENT,
           "granbond_wall_store_packed_len_in, another layout");
    EXPECT_NULL_ARG(granbond_wall_store_new(NULL), "granbond_wall_store_new", "store");
    EXPECT_NULL_ARG(granbond_wall_store_visit(store, NULL, &c, &v), "granbond_wall_store_visit", "model");
    EXPECT_NULL_ARG(granbond_wall_store_visit(store, m, NULL, &v), "granbond_wall_store_visit", "contact");
    EXPECT_NULL_ARG(granbond_wall_store_link(store, NULL), "granbond_wall_store_link", "ids");
    EXPECT_NULL_ARG(granbond_wall_store_counts(NULL, &counts), "granbond_wall_store_counts", "store");
    CHECK(granbond_wall_store_packed_len(NULL, 42) == 0 && granbond_wall_store_bytes(NULL) == 0,
          "a null store packs nothing");
    granbond_wall_store_free(other);
    granbond_wall_store_free(store);
    granbond_wall_store_free(NULL);
    granbond_bond_model_free(m);
    return 0;
}
