/*
 * abi_harness.c: proves the granbond C ABI from C.
 *
 * Calls every function declared in granbond.h, prints one line per check
 * ("ok   ..." or "FAIL ...") and returns non-zero at the first failure.
 * Built and run by rust-core/tests/c_abi.rs (`cargo test --test c_abi`),
 * which compiles it as C99 with -Wall -Wextra -Werror and links it against
 * libgranbond.a. It is also compiled (syntax only) as C++11, to prove the
 * header is C++-compatible, so it keeps to the common subset of C99 and
 * C++11: no designated initialisers, no compound literals, explicit casts.
 *
 * Expected values come from the models (docs/models/bond-nonlinear.md,
 * docs/models/voigt.md), evaluated here in C from the same inputs.
 */

#include "granbond.h"

#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

/* M_PI is POSIX, not C99. */
#define PI 3.14159265358979323846

/* ------------------------------------------------------------------------ */
/* Reporting                                                                 */
/* ------------------------------------------------------------------------ */

static int n_checks = 0;

static const char *status_name(GbStatus s)
{
    switch (s) {
    case GB_STATUS_OK:
        return "GB_STATUS_OK";
    case GB_STATUS_NULL_POINTER:
        return "GB_STATUS_NULL_POINTER";
    case GB_STATUS_INVALID_PARAMETER:
        return "GB_STATUS_INVALID_PARAMETER";
    case GB_STATUS_NON_FINITE_INPUT:
        return "GB_STATUS_NON_FINITE_INPUT";
    case GB_STATUS_COINCIDENT_CENTRES:
        return "GB_STATUS_COINCIDENT_CENTRES";
    case GB_STATUS_NON_POSITIVE_RADIUS:
        return "GB_STATUS_NON_POSITIVE_RADIUS";
    case GB_STATUS_LAYOUT_MISMATCH:
        return "GB_STATUS_LAYOUT_MISMATCH";
    case GB_STATUS_INVALID_ARGUMENT:
        return "GB_STATUS_INVALID_ARGUMENT";
    case GB_STATUS_PANIC:
        return "GB_STATUS_PANIC";
    }
    return "(unknown status)";
}

/* printf into a static buffer: a check description, used at once. */
static const char *say(const char *format, ...)
{
    static char buffer[512];
    va_list args;
    va_start(args, format);
    vsnprintf(buffer, sizeof buffer, format, args);
    va_end(args);
    return buffer;
}

static const char *last_message(void)
{
    const char *m = granbond_last_error_message();
    return m != NULL ? m : "(NULL)";
}

static int check_(int ok, const char *what, const char *condition, const char *file, int line)
{
    n_checks++;
    if (!ok) {
        printf("FAIL %s\n     at %s:%d: %s is false\n     last error message: \"%s\"\n", what, file, line,
               condition, last_message());
        return 0;
    }
    printf("ok   %s\n", what);
    return 1;
}

#define CHECK(cond, what)                                                                                    \
    do {                                                                                                     \
        if (!check_((cond) ? 1 : 0, (what), #cond, __FILE__, __LINE__))                                      \
            return 1;                                                                                        \
    } while (0)

/* A call's status; on success the thread's error must be cleared, on
 * failure there must be a message. */
static int expect_(GbStatus got, GbStatus want, const char *what, const char *file, int line)
{
    const char *message = granbond_last_error_message();
    int32_t parameter = granbond_last_error_parameter();
    n_checks++;
    if (message == NULL) {
        printf("FAIL %s\n     at %s:%d: granbond_last_error_message() returned NULL\n", what, file, line);
        return 0;
    }
    if (got != want) {
        printf("FAIL %s\n     at %s:%d: status %s (%d), expected %s (%d)\n     last error message: \"%s\"\n",
               what, file, line, status_name(got), (int)got, status_name(want), (int)want, message);
        return 0;
    }
    if (want == GB_STATUS_OK && (message[0] != '\0' || parameter != -1)) {
        printf("FAIL %s\n     at %s:%d: success left an error behind: message \"%s\", parameter %d\n", what,
               file, line, message, (int)parameter);
        return 0;
    }
    if (want != GB_STATUS_OK && message[0] == '\0') {
        printf("FAIL %s\n     at %s:%d: %s without a message\n", what, file, line, status_name(got));
        return 0;
    }
    if (want == GB_STATUS_OK)
        printf("ok   %s -> %s\n", what, status_name(got));
    else
        printf("ok   %s -> %s: %s\n", what, status_name(got), message);
    return 1;
}

#define EXPECT(call, want, what)                                                                             \
    do {                                                                                                     \
        if (!expect_((call), (want), (what), __FILE__, __LINE__))                                            \
            return 1;                                                                                        \
    } while (0)

#define EXPECT_OK(call, what) EXPECT(call, GB_STATUS_OK, what)

/* The last error message contains `needle`. */
static int message_has_(const char *needle, const char *file, int line)
{
    const char *m = last_message();
    n_checks++;
    if (strstr(m, needle) == NULL) {
        printf("FAIL message names \"%s\"\n     at %s:%d: message is \"%s\"\n", needle, file, line, m);
        return 0;
    }
    printf("ok   message names \"%s\"\n", needle);
    return 1;
}

#define EXPECT_MESSAGE(needle)                                                                               \
    do {                                                                                                     \
        if (!message_has_((needle), __FILE__, __LINE__))                                                     \
            return 1;                                                                                        \
    } while (0)

/* A NULL pointer argument: NULL_POINTER, a message naming the function and
 * the argument, no parameter id. */
static int null_arg_(GbStatus got, const char *function, const char *argument, const char *file, int line)
{
    char what[256];
    char needle[128];
    const char *m;
    snprintf(what, sizeof what, "%s with %s = NULL", function, argument);
    if (!expect_(got, GB_STATUS_NULL_POINTER, what, file, line))
        return 0;
    m = last_message();
    snprintf(needle, sizeof needle, "`%s`", argument);
    n_checks++;
    if (strstr(m, needle) == NULL || strstr(m, function) == NULL || strstr(m, "null") == NULL) {
        printf("FAIL %s\n     at %s:%d: message \"%s\" does not name the function and %s\n", what, file, line,
               m, needle);
        return 0;
    }
    if (granbond_last_error_parameter() != -1) {
        printf("FAIL %s\n     at %s:%d: parameter id %d after a pointer error\n", what, file, line,
               (int)granbond_last_error_parameter());
        return 0;
    }
    printf("ok   %s: message names %s\n", what, needle);
    return 1;
}

#define EXPECT_NULL_ARG(call, function, argument)                                                            \
    do {                                                                                                     \
        if (!null_arg_((call), (function), (argument), __FILE__, __LINE__))                                  \
            return 1;                                                                                        \
    } while (0)

/* ------------------------------------------------------------------------ */
/* Numbers and vectors                                                       */
/* ------------------------------------------------------------------------ */

static int close_to(double got, double want, double rel)
{
    if (!isfinite(got))
        return 0;
    if (want == 0.0)
        return fabs(got) <= rel;
    return fabs(got - want) <= rel * fabs(want);
}

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static double norm3(const double a[3])
{
    return sqrt(dot3(a, a));
}

static double distance3(const double a[3], const double b[3])
{
    double d[3];
    d[0] = a[0] - b[0];
    d[1] = a[1] - b[1];
    d[2] = a[2] - b[2];
    return norm3(d);
}

/* |got - want| <= rel |want| */
static int vec_close(const double got[3], const double want[3], double rel)
{
    double d[3];
    int c;
    for (c = 0; c < 3; c++) {
        if (!isfinite(got[c]))
            return 0;
        d[c] = got[c] - want[c];
    }
    return norm3(d) <= rel * norm3(want);
}

static int vec_zero(const double v[3])
{
    return v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0;
}

/* ------------------------------------------------------------------------ */
/* Fixtures                                                                  */
/* ------------------------------------------------------------------------ */

/* Bond fixture: spheres of radii R_I > R_J, touching at creation. */
#define R_I 1.0e-3
#define R_J 0.8e-3
#define R0_NOMINAL (R_I + R_J)
#define LAMBDA 0.5
#define CREATE_DISTANCE 2.0e-3
#define MAX_DISTANCE 1.9e-3
#define CREATE_STEP 7
#define DT 1.0e-7

/* Direction of the centre line (not along an axis): (2, 3, 6) / 7. */
static const double AXIS[3] = {2.0 / 7.0, 3.0 / 7.0, 6.0 / 7.0};
static const double X_J[3] = {1.0e-3, -2.0e-3, 0.5e-3};

/* Sphere j at X_J, sphere i at distance r along AXIS; at rest. */
static void pair_at(GbPairKinematics *k, double r, double radius_i, double radius_j)
{
    int c;
    memset(k, 0, sizeof *k);
    for (c = 0; c < 3; c++) {
        k->x_j[c] = X_J[c];
        k->x_i[c] = X_J[c] + r * AXIS[c];
    }
    k->radius_i = radius_i;
    k->radius_j = radius_j;
}

static GbBondParams bond_fixture(void)
{
    GbBondParams p;
    memset(&p, 0, sizeof p);
    granbond_bond_params_default(&p);
    p.lambda = LAMBDA;
    p.k_fn1 = 2.0e9;
    p.ku_fn1 = 4.0e9;
    p.kc_fn1 = 1.0e8;
    p.k_fn2 = 1.0e10;
    p.ku_fn2 = 1.0e10;
    p.kc_fn2 = 1.0e9;
    p.k_ft = 5.0e9;
    p.k_tn = 1.0e9;
    p.ku_tn = 2.0e9;
    p.kc_tn = 1.0e8;
    p.k_tt = 1.0e9;
    p.ku_tt = 2.0e9;
    p.kc_tt = 1.0e8;
    p.max_distance = MAX_DISTANCE;
    p.create_distance = CREATE_DISTANCE;
    p.create_step = CREATE_STEP;
    return p;
}

static GbVoigtParams voigt_fixture(void)
{
    GbVoigtParams p;
    memset(&p, 0, sizeof p);
    granbond_voigt_params_default(&p);
    return p;
}

/* Index of the slot called `name` in a state of `kind`, or -1. */
static int slot_index(int32_t kind, const char *name)
{
    size_t i, len = granbond_state_len(kind);
    for (i = 0; i < len; i++) {
        const char *slot = NULL;
        int32_t flips = 0;
        if (granbond_state_slot(kind, i, &slot, &flips) == GB_STATUS_OK && strcmp(slot, name) == 0)
            return (int)i;
    }
    return -1;
}

/* Something non-NULL to preset output pointers with. */
static unsigned char sentinel_object[16];

/* ------------------------------------------------------------------------ */
/* ABI version and layout                                                    */
/* ------------------------------------------------------------------------ */

static GbLayout caller_layout(void)
{
    return granbond_header_layout();
}

struct layout_item {
    const char *message_names;
    size_t offset;
};

static int test_version_and_layout(void)
{
    static const struct layout_item items[] = {
        {"sizeof(GbBondParams)", offsetof(GbLayout, bond_params)},
        {"sizeof(GbVoigtParams)", offsetof(GbLayout, voigt_params)},
        {"sizeof(GbPairKinematics)", offsetof(GbLayout, pair_kinematics)},
        {"sizeof(GbSphereKinematics)", offsetof(GbLayout, sphere_kinematics)},
        {"sizeof(GbPlane)", offsetof(GbLayout, plane)},
        {"sizeof(GbBondOutput)", offsetof(GbLayout, bond_output)},
        {"sizeof(GbContactOutput)", offsetof(GbLayout, contact_output)},
        {"sizeof(GbContactFrame)", offsetof(GbLayout, contact_frame)},
        {"sizeof(GbTangentialOutput)", offsetof(GbLayout, tangential_output)},
        {"bond state length", offsetof(GbLayout, bond_state_len)},
        {"wall bond state length", offsetof(GbLayout, wall_bond_state_len)},
        {"contact state length", offsetof(GbLayout, contact_state_len)},
    };
    GbLayout l;
    size_t i;

    CHECK(granbond_abi_version() == GRANBOND_ABI_VERSION,
          say("granbond_abi_version() = %u = GRANBOND_ABI_VERSION", (unsigned)granbond_abi_version()));
    CHECK(GRANBOND_WALL_BOND_STATE_LEN == GRANBOND_BOND_STATE_LEN + 3, "wall bond state = bond state + 3");

    l = caller_layout();
    EXPECT_OK(granbond_check_layout(&l), "granbond_check_layout(layout of this header)");

    for (i = 0; i < sizeof items / sizeof items[0]; i++) {
        l = caller_layout();
        *(size_t *)(void *)((char *)&l + items[i].offset) += 8;
        EXPECT(granbond_check_layout(&l), GB_STATUS_LAYOUT_MISMATCH,
               say("granbond_check_layout with a wrong %s", items[i].message_names));
        EXPECT_MESSAGE(items[i].message_names);
    }
    l = caller_layout();
    l.bond_params = sizeof(GbBondParams) - 8;
    EXPECT(granbond_check_layout(&l), GB_STATUS_LAYOUT_MISMATCH, "granbond_check_layout, GbBondParams too small");
    EXPECT_MESSAGE("GbBondParams");
    l = caller_layout();
    l.abi_version = GRANBOND_ABI_VERSION + 1;
    EXPECT(granbond_check_layout(&l), GB_STATUS_LAYOUT_MISMATCH, "granbond_check_layout with a newer abi_version");
    EXPECT_MESSAGE("abi_version");
    CHECK(granbond_last_error_parameter() == -1, "no parameter id after a layout mismatch");
    /* A caller whose GbLayout has another size (older or newer header) is
     * refused from the first two fields, before anything else is read. */
    l = caller_layout();
    l.layout_size = sizeof(GbLayout) - sizeof(size_t);
    EXPECT(granbond_check_layout(&l), GB_STATUS_LAYOUT_MISMATCH, "granbond_check_layout, shorter GbLayout");
    EXPECT_MESSAGE("sizeof(GbLayout)");

    EXPECT_NULL_ARG(granbond_check_layout(NULL), "granbond_check_layout", "expected");
    return 0;
}

/* ------------------------------------------------------------------------ */
/* State layout                                                              */
/* ------------------------------------------------------------------------ */

static int expect_slot(int32_t kind, size_t index, const char *name, int32_t flips)
{
    const char *got = NULL;
    int32_t got_flips = -1;
    EXPECT_OK(granbond_state_slot(kind, index, &got, &got_flips), say("granbond_state_slot(%d, %u)", (int)kind,
                                                                      (unsigned)index));
    CHECK(got != NULL && strcmp(got, name) == 0, say("slot %u of kind %d is \"%s\"", (unsigned)index, (int)kind,
                                                     name));
    CHECK(got_flips == flips, say("slot \"%s\" flips_on_swap = %d", name, (int)flips));
    return 0;
}

static int test_state_layout(void)
{
    static const int32_t kinds[3] = {GB_STATE_KIND_BOND, GB_STATE_KIND_WALL_BOND, GB_STATE_KIND_CONTACT};
    static const size_t lengths[3] = {GRANBOND_BOND_STATE_LEN, GRANBOND_WALL_BOND_STATE_LEN,
                                      GRANBOND_CONTACT_STATE_LEN};
    const char *name = NULL;
    int32_t flips = 0;
    int k;

    for (k = 0; k < 3; k++)
        CHECK(granbond_state_len(kinds[k]) == lengths[k],
              say("granbond_state_len(%d) = %u", (int)kinds[k], (unsigned)lengths[k]));
    CHECK(granbond_state_len(3) == 0, "granbond_state_len(3) = 0 (unknown kind)");
    CHECK(granbond_state_len(-1) == 0, "granbond_state_len(-1) = 0 (unknown kind)");

    if (expect_slot(GB_STATE_KIND_BOND, 0, "status", 0) || expect_slot(GB_STATE_KIND_BOND, 1, "r0", 0) ||
        expect_slot(GB_STATE_KIND_BOND, 2, "delta_max", 0) || expect_slot(GB_STATE_KIND_BOND, 3, "delta_min", 0) ||
        expect_slot(GB_STATE_KIND_BOND, 4, "shear_force_x", 1) ||
        expect_slot(GB_STATE_KIND_BOND, 12, "bend_angle_z", 1) ||
        expect_slot(GB_STATE_KIND_BOND, 13, "twist_max", 0) ||
        expect_slot(GB_STATE_KIND_BOND, 14, "twist_min", 0) ||
        expect_slot(GB_STATE_KIND_BOND, 15, "bend_history_x", 1) ||
        expect_slot(GB_STATE_KIND_BOND, 17, "bend_history_z", 1) ||
        expect_slot(GB_STATE_KIND_BOND, 18, "bend_opposite", 0) ||
        expect_slot(GB_STATE_KIND_WALL_BOND, 0, "status", 0) ||
        expect_slot(GB_STATE_KIND_WALL_BOND, 19, "partner_x", 0) ||
        expect_slot(GB_STATE_KIND_WALL_BOND, 21, "partner_z", 0) ||
        expect_slot(GB_STATE_KIND_CONTACT, 0, "tangential_spring_x", 1) ||
        expect_slot(GB_STATE_KIND_CONTACT, 5, "rolling_angle_z", 1))
        return 1;

    /* Every slot: a non-empty name, unique within its kind. */
    for (k = 0; k < 3; k++) {
        size_t i, j, len = lengths[k];
        int all_named = 1, unique = 1;
        for (i = 0; i < len; i++) {
            const char *a = NULL;
            int32_t fa = -1;
            EXPECT_OK(granbond_state_slot(kinds[k], i, &a, &fa),
                      say("granbond_state_slot(%d, %u)", (int)kinds[k], (unsigned)i));
            if (a == NULL || a[0] == '\0' || (fa != 0 && fa != 1))
                all_named = 0;
            for (j = 0; a != NULL && j < i; j++) {
                const char *b = NULL;
                int32_t fb = 0;
                granbond_state_slot(kinds[k], j, &b, &fb);
                if (b != NULL && strcmp(a, b) == 0)
                    unique = 0;
            }
        }
        CHECK(all_named, say("kind %d: every slot has a name and a 0/1 swap flag", (int)kinds[k]));
        CHECK(unique, say("kind %d: slot names are unique", (int)kinds[k]));
    }
    /* The wall bond state starts with the pair bond state. */
    {
        size_t i;
        int same = 1;
        for (i = 0; i < GRANBOND_BOND_STATE_LEN; i++) {
            const char *a = NULL, *b = NULL;
            int32_t fa = 0, fb = 0;
            granbond_state_slot(GB_STATE_KIND_BOND, i, &a, &fa);
            granbond_state_slot(GB_STATE_KIND_WALL_BOND, i, &b, &fb);
            if (a == NULL || b == NULL || strcmp(a, b) != 0 || fa != fb)
                same = 0;
        }
        CHECK(same, "wall bond slots 0..14 are the bond slots");
    }

    EXPECT(granbond_state_slot(GB_STATE_KIND_BOND, GRANBOND_BOND_STATE_LEN, &name, &flips),
           GB_STATUS_INVALID_ARGUMENT, "granbond_state_slot(bond, GRANBOND_BOND_STATE_LEN)");
    EXPECT_MESSAGE("out of range");
    EXPECT(granbond_state_slot(GB_STATE_KIND_WALL_BOND, GRANBOND_WALL_BOND_STATE_LEN, &name, &flips),
           GB_STATUS_INVALID_ARGUMENT, "granbond_state_slot(wall bond, GRANBOND_WALL_BOND_STATE_LEN)");
    EXPECT(granbond_state_slot(GB_STATE_KIND_CONTACT, (size_t)-1, &name, &flips), GB_STATUS_INVALID_ARGUMENT,
           "granbond_state_slot(contact, SIZE_MAX)");
    EXPECT(granbond_state_slot(3, 0, &name, &flips), GB_STATUS_INVALID_ARGUMENT, "granbond_state_slot(kind 3, 0)");
    EXPECT_MESSAGE("unknown state kind");
    EXPECT(granbond_state_slot(-1, 0, &name, &flips), GB_STATUS_INVALID_ARGUMENT,
           "granbond_state_slot(kind -1, 0)");
    CHECK(granbond_last_error_parameter() == -1, "no parameter id after an invalid argument");

    EXPECT_NULL_ARG(granbond_state_slot(GB_STATE_KIND_BOND, 0, NULL, &flips), "granbond_state_slot", "name");
    EXPECT_NULL_ARG(granbond_state_slot(GB_STATE_KIND_BOND, 0, &name, NULL), "granbond_state_slot",
                    "flips_on_swap");
    return 0;
}

/* ------------------------------------------------------------------------ */
/* Bond parameters                                                           */
/* ------------------------------------------------------------------------ */

enum field_type { F_DOUBLE, F_INT64, F_INT32 };

struct field {
    const char *keyword;
    const char *liggghts;
    size_t offset;
    enum field_type type;
};

/* A parameter table as the library describes it. */
struct table {
    const char *what;
    size_t size; /* of the parameter struct */
    size_t (*count)(void);
    GbStatus (*info)(size_t, GbParameterInfo *);
    GbStatus (*set)(void *, const char *, double);
    GbStatus (*defaults)(void *);
};

static GbStatus bond_set(void *p, const char *name, double v) { return granbond_bond_params_set((GbBondParams *)p, name, v); }
static GbStatus bond_defaults(void *p) { return granbond_bond_params_default((GbBondParams *)p); }
static GbStatus voigt_set(void *p, const char *name, double v) { return granbond_voigt_params_set((GbVoigtParams *)p, name, v); }
static GbStatus voigt_defaults(void *p) { return granbond_voigt_params_default((GbVoigtParams *)p); }

static const struct table BOND_TABLE = {"bond", sizeof(GbBondParams), granbond_bond_parameter_count,
                                        granbond_bond_parameter_info, bond_set, bond_defaults};
static const struct table VOIGT_TABLE = {"voigt", sizeof(GbVoigtParams), granbond_voigt_parameter_count,
                                         granbond_voigt_parameter_info, voigt_set, voigt_defaults};

#define MAX_FIELDS 64
#define MAX_PARAMS_SIZE 512

static double field_value(const unsigned char *params, size_t offset, enum field_type type)
{
    double d;
    int64_t i64;
    int32_t i32;
    switch (type) {
    case F_DOUBLE: memcpy(&d, params + offset, sizeof d); return d;
    case F_INT64: memcpy(&i64, params + offset, sizeof i64); return (double)i64;
    default: memcpy(&i32, params + offset, sizeof i32); return (double)i32;
    }
}

/* Reads the library's table `t` into `fields`, finding each row's field by
 * setting the row by name and looking for the bytes that changed. So the
 * rows are checked against the header's struct (one row per field, in
 * declaration order, each name setting its own field, the default the
 * struct's default) without a copy of the table here. */
static int load_table(const struct table *t, struct field *fields, size_t *n)
{
    unsigned char base[MAX_PARAMS_SIZE], p[MAX_PARAMS_SIZE], q[MAX_PARAMS_SIZE];
    size_t i, k, end = 0;

    *n = t->count();
    CHECK(*n > 0 && *n <= MAX_FIELDS, say("%s table has 1..%d rows", t->what, MAX_FIELDS));
    CHECK(t->size <= MAX_PARAMS_SIZE, say("%s parameters fit the scratch buffer", t->what));
    EXPECT_OK(t->defaults(base), say("%s defaults", t->what));
    for (i = 0; i < *n; i++) {
        GbParameterInfo info;
        enum field_type type;
        size_t width, first = (size_t)-1, last = 0, offset;
        double v;

        EXPECT_OK(t->info(i, &info), say("%s parameter info %u", t->what, (unsigned)i));
        CHECK(info.keyword && info.liggghts_name && info.unit && info.range && info.needed_when,
              say("%s parameter %u has its names, unit, range and need", t->what, (unsigned)i));
        type = info.kind == GB_PARAMETER_KIND_REAL ? F_DOUBLE
               : info.kind == GB_PARAMETER_KIND_INTEGER ? F_INT64 : F_INT32;
        width = type == F_INT32 ? 4 : 8;
        v = type == F_INT32 ? 1.0 - info.default_value
            : type == F_INT64 ? 41.0 : (info.default_value == 0.375 ? 0.25 : 0.375);
        memcpy(p, base, t->size);
        EXPECT_OK(t->set(p, info.keyword, v), say("%s set %s = %g", t->what, info.keyword, v));
        for (k = 0; k < t->size; k++)
            if (p[k] != base[k]) {
                if (first == (size_t)-1)
                    first = k;
                last = k;
            }
        CHECK(first != (size_t)-1, say("setting %s changes the parameters", info.keyword));
        offset = first - first % width;
        CHECK(last < offset + width, say("setting %s changes one field", info.keyword));
        CHECK(offset == (end + width - 1) / width * width,
              say("%s is the field after the previous row's (declaration order, no gap)", info.keyword));
        CHECK(field_value(p, offset, type) == v, say("%s = %g reads back", info.keyword, v));
        CHECK(field_value(base, offset, type) == info.default_value ||
                  (isnan(info.default_value) && isnan(field_value(base, offset, type))),
              say("%s default %g is the struct's", info.keyword, info.default_value));
        memcpy(q, base, t->size);
        EXPECT_OK(t->set(q, info.liggghts_name, v), say("%s set by LIGGGHTS name %s", t->what, info.liggghts_name));
        CHECK(memcmp(p, q, t->size) == 0, say("%s and %s set the same field", info.keyword, info.liggghts_name));
        end = offset + width;
        fields[i].keyword = info.keyword;
        fields[i].liggghts = info.liggghts_name;
        fields[i].offset = offset;
        fields[i].type = type;
    }
    CHECK((end + 7) / 8 * 8 == t->size, say("the %s rows cover the whole struct", t->what));
    return 0;
}

static struct field BOND_FIELDS[MAX_FIELDS];
static size_t N_BOND_FIELDS;
static struct field VOIGT_FIELDS[MAX_FIELDS];
static size_t N_VOIGT_FIELDS;

static int test_parameter_tables(void)
{
    GbBondParams p;
    if (load_table(&BOND_TABLE, BOND_FIELDS, &N_BOND_FIELDS) || load_table(&VOIGT_TABLE, VOIGT_FIELDS, &N_VOIGT_FIELDS))
        return 1;
    granbond_bond_params_default(&p);
    EXPECT(granbond_bond_params_set(&p, "k_fnl", 1.0), GB_STATUS_INVALID_ARGUMENT, "set an unknown name");
    EXPECT_MESSAGE("k_fnl");
    EXPECT_MESSAGE("known: lambda k_fn1");
    EXPECT(granbond_bond_params_set(&p, "stiffnessPerUnitAreaK_fn1", -1.0), GB_STATUS_INVALID_PARAMETER,
           "set k_fn1 = -1");
    EXPECT_MESSAGE("k_fn1 (stiffnessPerUnitAreaK_fn1) must be finite and >= 0; got -1");
    CHECK(granbond_last_error_parameter() == 1, "the refused row's id");
    EXPECT(granbond_bond_params_set(&p, "damping", 0.5), GB_STATUS_INVALID_PARAMETER, "set damping = 0.5");
    EXPECT(granbond_bond_params_set(&p, "create_step", 2.5), GB_STATUS_INVALID_PARAMETER, "set create_step = 2.5");
    EXPECT_NULL_ARG(granbond_bond_params_set(NULL, "lambda", 1.0), "granbond_bond_params_set", "params");
    EXPECT_NULL_ARG(granbond_bond_params_set(&p, NULL, 1.0), "granbond_bond_params_set", "name");
    EXPECT_NULL_ARG(granbond_bond_parameter_info(0, NULL), "granbond_bond_parameter_info", "info");
    {
        GbParameterInfo info;
        int32_t needed = -1;
        size_t eta = 14, max_sigma = 19;
        EXPECT(granbond_bond_parameter_info(N_BOND_FIELDS, &info), GB_STATUS_INVALID_ARGUMENT, "info(count)");
        EXPECT_MESSAGE("out of range");
        granbond_bond_params_default(&p);
        CHECK(strcmp(BOND_FIELDS[eta].keyword, "eta_fn") == 0 && strcmp(BOND_FIELDS[max_sigma].keyword, "max_sigma") == 0,
              "rows 14 and 19 are eta_fn and max_sigma");
        EXPECT_OK(granbond_bond_parameter_needed(&p, max_sigma, &needed), "needed(max_sigma)");
        CHECK(needed == 0, "max_sigma is not read in distance mode");
        p.stress_break = 1;
        EXPECT_OK(granbond_bond_parameter_needed(&p, max_sigma, &needed), "needed(max_sigma)");
        CHECK(needed == 1, "max_sigma is read in stress mode");
        p.damping = 0;
        p.damping_smooth = 1;
        EXPECT_OK(granbond_bond_parameter_needed(&p, eta, &needed), "needed(eta_fn)");
        CHECK(needed == 1, "smooth damping reads the damping ratios");
        EXPECT_NULL_ARG(granbond_bond_parameter_needed(&p, eta, NULL), "granbond_bond_parameter_needed", "needed");
        EXPECT_NULL_ARG(granbond_bond_parameter_needed(NULL, eta, &needed), "granbond_bond_parameter_needed",
                        "params");
    }
    {
        GbVoigtParams v;
        GbParameterInfo info;
        int32_t needed = -1;
        size_t k_r = 5;
        EXPECT(granbond_voigt_parameter_info(N_VOIGT_FIELDS, &info), GB_STATUS_INVALID_ARGUMENT, "voigt info(count)");
        CHECK(strcmp(VOIGT_FIELDS[k_r].keyword, "k_r") == 0, "voigt row 5 is k_r");
        granbond_voigt_params_default(&v);
        v.rolling = 0;
        EXPECT_OK(granbond_voigt_parameter_needed(&v, k_r, &needed), "voigt needed(k_r)");
        CHECK(needed == 0, "k_r is not read without rolling");
        EXPECT_OK(granbond_voigt_params_set(&v, "rolling", 1.0), "voigt set rolling = 1");
        EXPECT_OK(granbond_voigt_parameter_needed(&v, k_r, &needed), "voigt needed(k_r)");
        CHECK(needed == 1, "k_r is read with rolling");
    }
    return 0;
}

static size_t bond_field_id(const char *keyword)
{
    size_t i;
    for (i = 0; i < N_BOND_FIELDS; i++)
        if (strcmp(BOND_FIELDS[i].keyword, keyword) == 0)
            return i;
    return (size_t)-1;
}

static double *double_field(void *params, size_t offset)
{
    return (double *)(void *)((char *)params + offset);
}

static int32_t *int32_field(void *params, size_t offset)
{
    return (int32_t *)(void *)((char *)params + offset);
}

/* model_new refuses `p`: INVALID_PARAMETER, *model reset to NULL, the
 * parameter id of `keyword`, its names (and `also`, unless NULL) in the
 * message, and the same names from granbond_bond_parameter_name. */
static int expect_bond_refused(const GbBondParams *p, const char *keyword, const char *also, const char *what)
{
    GbBondModel *m = (GbBondModel *)(void *)sentinel_object;
    size_t id = bond_field_id(keyword);
    const char *kw = NULL, *lg = NULL;
    char both[256];
    int32_t reported;

    EXPECT(granbond_bond_model_new(p, &m), GB_STATUS_INVALID_PARAMETER, what);
    reported = granbond_last_error_parameter();
    CHECK(m == NULL, "granbond_bond_model_new sets *model = NULL on failure");
    CHECK(id != (size_t)-1, say("%s is a field of GbBondParams", keyword));
    snprintf(both, sizeof both, "%s (%s)", BOND_FIELDS[id].keyword, BOND_FIELDS[id].liggghts);
    EXPECT_MESSAGE(both);
    if (also != NULL)
        EXPECT_MESSAGE(also);
    CHECK(reported == (int32_t)id, say("granbond_last_error_parameter() = %d = id of %s", (int)id, keyword));
    EXPECT_OK(granbond_bond_parameter_name((size_t)reported, &kw, &lg),
              say("granbond_bond_parameter_name(%d)", (int)reported));
    CHECK(kw != NULL && strcmp(kw, keyword) == 0, say("parameter %d is keyword \"%s\"", (int)reported, keyword));
    CHECK(lg != NULL && strcmp(lg, BOND_FIELDS[id].liggghts) == 0,
          say("parameter %d is LIGGGHTS \"%s\"", (int)reported, BOND_FIELDS[id].liggghts));
    return 0;
}

static int test_bond_params(void)
{
    GbBondParams p, base;
    GbBondModel *m = NULL;
    const char *kw = NULL, *lg = NULL;
    size_t i;

    /* Defaults (spec: switch defaults of the reference; breakage off). */
    memset(&p, 0xAB, sizeof p);
    EXPECT_OK(granbond_bond_params_default(&p), "granbond_bond_params_default");
    CHECK(p.lambda == 1.0, "default lambda = 1");
    CHECK(p.k_fn1 == 0.0 && p.k_fn2 == 0.0 && p.k_ft == 0.0 && p.k_tn == 0.0 && p.k_tt == 0.0,
          "default stiffnesses = 0");
    CHECK(isinf(p.max_distance) && p.max_distance > 0.0, "default max_distance = +inf");
    CHECK(isinf(p.max_sigma) && isinf(p.max_tau), "default max_sigma = max_tau = +inf");
    CHECK(p.tension_compression_ratio == 1.0, "default ratio = 1");
    CHECK(p.create_step == 0 && p.create_distance == 0.0, "default create_step = 0, create_distance = 0");
    CHECK(p.stress_break == 0 && p.use_ratio == 0 && p.create_always == 0 && p.history_reset == 0 &&
              p.damping_smooth == 0,
          "default stressBreak, ratioTensionCompressionBond, createBondAlways, historyReset, dampingBondSmooth off");
    CHECK(p.damping == 1 && p.tension == 1 && p.compression == 1 && p.shear == 1 && p.twist == 1 && p.bend == 1,
          "default dampingBond and the five degrees of freedom on");
    EXPECT_OK(granbond_bond_model_new(&p, &m), "granbond_bond_model_new(defaults)");
    CHECK(m != NULL, "model created from the defaults");
    granbond_bond_model_free(m);
    m = NULL;

    /* The parameter table: one row per field, in field order. */
    CHECK(granbond_bond_parameter_count() == N_BOND_FIELDS,
          say("granbond_bond_parameter_count() = %u = fields of GbBondParams", (unsigned)N_BOND_FIELDS));
    for (i = 0; i < N_BOND_FIELDS; i++) {
        EXPECT_OK(granbond_bond_parameter_name(i, &kw, &lg), say("granbond_bond_parameter_name(%u)", (unsigned)i));
        CHECK(kw != NULL && lg != NULL && strcmp(kw, BOND_FIELDS[i].keyword) == 0 &&
                  strcmp(lg, BOND_FIELDS[i].liggghts) == 0,
              say("parameter %u = %s / %s", (unsigned)i, BOND_FIELDS[i].keyword, BOND_FIELDS[i].liggghts));
    }
    EXPECT_OK(granbond_bond_parameter_name(bond_field_id("k_fn1"), &kw, &lg), "granbond_bond_parameter_name(k_fn1)");
    CHECK(strcmp(kw, "k_fn1") == 0 && strcmp(lg, "stiffnessPerUnitAreaK_fn1") == 0,
          "k_fn1 <-> stiffnessPerUnitAreaK_fn1");
    EXPECT(granbond_bond_parameter_name(N_BOND_FIELDS, &kw, &lg), GB_STATUS_INVALID_ARGUMENT,
           "granbond_bond_parameter_name(count)");
    EXPECT_MESSAGE("out of range");
    EXPECT_NULL_ARG(granbond_bond_parameter_name(0, NULL, &lg), "granbond_bond_parameter_name", "keyword");
    EXPECT_NULL_ARG(granbond_bond_parameter_name(0, &kw, NULL), "granbond_bond_parameter_name", "liggghts_name");

    /* A good parameter set. */
    base = bond_fixture();
    EXPECT_OK(granbond_bond_model_new(&base, &m), "granbond_bond_model_new(fixture)");
    CHECK(m != NULL, "model created");
    granbond_bond_model_free(m);
    m = NULL;
    p = base;
    p.eta_fn = 0.99;
    p.max_distance = INFINITY;
    p.create_step = -5;
    p.ku_fn1 = p.k_fn1; /* ku = k: no hysteresis, allowed */
    EXPECT_OK(granbond_bond_model_new(&p, &m), "eta_fn = 0.99, max_distance = inf, create_step = -5, ku = k");
    granbond_bond_model_free(m);
    m = NULL;

    /* The cases named in the brief. */
    p = base;
    p.k_fn1 = -1.0;
    if (expect_bond_refused(&p, "k_fn1", "got -1", "k_fn1 = -1"))
        return 1;
    p = base;
    p.eta_fn = 1.5;
    if (expect_bond_refused(&p, "eta_fn", NULL, "eta_fn = 1.5"))
        return 1;
    p = base;
    p.eta_fn = 1.0;
    if (expect_bond_refused(&p, "eta_fn", NULL, "eta_fn = 1 (damping ratio must be < 1)"))
        return 1;
    p = base;
    p.lambda = 0.0;
    if (expect_bond_refused(&p, "lambda", NULL, "lambda = 0"))
        return 1;
    p = base;
    p.ku_fn1 = 0.5 * p.k_fn1;
    if (expect_bond_refused(&p, "ku_fn1", ">= k_fn1", "ku_fn1 < k_fn1"))
        return 1;
    p = base;
    p.ku_tt = 0.5 * p.k_tt;
    if (expect_bond_refused(&p, "ku_tt", NULL, "ku_tt < k_tt"))
        return 1;
    p = base;
    p.stress_break = 2;
    if (expect_bond_refused(&p, "stress_break", NULL, "stress_break = 2"))
        return 1;
    p = base;
    p.twist = -1;
    if (expect_bond_refused(&p, "twist", NULL, "twist = -1"))
        return 1;
    p = base;
    p.k_fn2 = NAN;
    if (expect_bond_refused(&p, "k_fn2", NULL, "k_fn2 = NaN"))
        return 1;
    p = base;
    p.max_distance = 0.0;
    if (expect_bond_refused(&p, "max_distance", NULL, "max_distance = 0"))
        return 1;
    p = base;
    p.create_distance = INFINITY;
    if (expect_bond_refused(&p, "create_distance", NULL, "create_distance = inf"))
        return 1;

    /* Every field: a value out of range is refused with its own id. */
    for (i = 0; i < N_BOND_FIELDS; i++) {
        const struct field *f = &BOND_FIELDS[i];
        p = base;
        if (f->type == F_DOUBLE) {
            *double_field(&p, f->offset) = NAN;
            if (expect_bond_refused(&p, f->keyword, NULL, say("%s = NaN", f->keyword)))
                return 1;
            p = base;
            *double_field(&p, f->offset) = -INFINITY;
            if (expect_bond_refused(&p, f->keyword, NULL, say("%s = -inf", f->keyword)))
                return 1;
        } else if (f->type == F_INT32) {
            *int32_field(&p, f->offset) = 2;
            if (expect_bond_refused(&p, f->keyword, NULL, say("%s = 2", f->keyword)))
                return 1;
        }
    }

    EXPECT_NULL_ARG(granbond_bond_params_default(NULL), "granbond_bond_params_default", "params");
    m = (GbBondModel *)(void *)sentinel_object;
    EXPECT_NULL_ARG(granbond_bond_model_new(NULL, &m), "granbond_bond_model_new", "params");
    CHECK(m == NULL, "granbond_bond_model_new(NULL params) sets *model = NULL");
    EXPECT_NULL_ARG(granbond_bond_model_new(&base, NULL), "granbond_bond_model_new", "model");
    return 0;
}

/* ------------------------------------------------------------------------ */
/* Bonds between two spheres                                                 */
/* ------------------------------------------------------------------------ */

static int new_bond_model(const GbBondParams *p, GbBondModel **m)
{
    *m = NULL;
    EXPECT_OK(granbond_bond_model_new(p, m), "granbond_bond_model_new");
    CHECK(*m != NULL, "model is not NULL");
    return 0;
}

/* A bond created at the fixture's rest length in `state`. */
static int create_bond(const GbBondModel *m, double *state)
{
    GbPairKinematics k;
    int32_t created = -1;
    memset(state, 0, GRANBOND_BOND_STATE_LEN * sizeof(double));
    pair_at(&k, R0_NOMINAL, R_I, R_J);
    {
        /* Immediate creation ignores the step, not the distance. */
        double fresh[GRANBOND_BOND_STATE_LEN] = {0};
        int32_t now = -1;
        EXPECT_OK(granbond_bond_create_now(m, &k, fresh, &now), "granbond_bond_create_now");
        CHECK(now == 1 && fresh[0] == 1.0, "granbond_bond_create_now bonds at any step");
        EXPECT_OK(granbond_bond_create_now(m, &k, fresh, &now), "granbond_bond_create_now, intact");
        CHECK(now == 0, "granbond_bond_create_now keeps an intact bond");
        EXPECT_NULL_ARG(granbond_bond_create_now(NULL, &k, fresh, &now), "granbond_bond_create_now", "model");
        EXPECT_NULL_ARG(granbond_bond_create_now(m, NULL, fresh, &now), "granbond_bond_create_now", "kinematics");
        EXPECT_NULL_ARG(granbond_bond_create_now(m, &k, NULL, &now), "granbond_bond_create_now", "state");
        EXPECT_NULL_ARG(granbond_bond_create_now(m, &k, fresh, NULL), "granbond_bond_create_now", "created");
    }
    EXPECT_OK(granbond_bond_try_create(m, &k, CREATE_STEP, state, &created), "granbond_bond_try_create");
    CHECK(created == 1, "bond created");
    return 0;
}

static int test_bond_create_and_force(void)
{
    const GbBondParams p = bond_fixture();
    GbBondModel *m = NULL;
    GbPairKinematics k;
    GbBondOutput out;
    double state[GRANBOND_BOND_STATE_LEN], copy[GRANBOND_BOND_STATE_LEN];
    double n[3], expected[3], r, r0, delta, rb, area, fn;
    int32_t created = -1;
    int c, i_status, i_r0, i_dmin, i_dmax;
    const double stretch = 1.0e-5, squeeze = 1.0e-5;

    if (new_bond_model(&p, &m))
        return 1;
    i_status = slot_index(GB_STATE_KIND_BOND, "status");
    i_r0 = slot_index(GB_STATE_KIND_BOND, "r0");
    i_dmin = slot_index(GB_STATE_KIND_BOND, "delta_min");
    i_dmax = slot_index(GB_STATE_KIND_BOND, "delta_max");
    CHECK(i_status >= 0 && i_r0 >= 0 && i_dmin >= 0 && i_dmax >= 0, "slots status, r0, delta_min, delta_max found");

    /* Creation rules. What granbond_bond_may_create says of a state and a
     * step: unbonded, only at create_step (create_always is off); intact
     * never; broken only with create_always; 0 for bad pointers. */
    memset(state, 0, sizeof state);
    CHECK(granbond_bond_may_create(m, state, CREATE_STEP) == 1, "may_create: unbonded, at create_step");
    CHECK(granbond_bond_may_create(m, state, CREATE_STEP - 1) == 0 &&
              granbond_bond_may_create(m, state, CREATE_STEP + 1) == 0,
          "may_create: unbonded, not at create_step");
    state[i_status] = GB_BOND_STATUS_INTACT;
    CHECK(granbond_bond_may_create(m, state, CREATE_STEP) == 0, "may_create: intact");
    state[i_status] = GB_BOND_STATUS_BROKEN;
    CHECK(granbond_bond_may_create(m, state, CREATE_STEP) == 0, "may_create: broken, create_always off");
    {
        GbBondParams always = p;
        GbBondModel *ma = NULL;
        always.create_always = 1;
        if (new_bond_model(&always, &ma))
            return 1;
        CHECK(granbond_bond_may_create(ma, state, CREATE_STEP + 7) == 1, "may_create: broken, create_always on");
        granbond_bond_model_free(ma);
    }
    CHECK(granbond_bond_may_create(NULL, state, CREATE_STEP) == 0 && granbond_bond_may_create(m, NULL, CREATE_STEP) == 0 &&
              granbond_bond_may_create(m, (const double *)((const char *)state + 1), CREATE_STEP) == 0,
          "may_create: 0 for a null model, a null or misaligned state");
    memset(state, 0, sizeof state);
    pair_at(&k, R0_NOMINAL, R_I, R_J);
    EXPECT_OK(granbond_bond_try_create(m, &k, CREATE_STEP - 1, state, &created),
              "try_create within create_distance, not at create_step");
    CHECK(created == 0, "not created before create_step");
    CHECK(state[i_status] == 0.0 && state[i_r0] == 0.0, "state still unbonded");
    pair_at(&k, CREATE_DISTANCE * 1.05, R_I, R_J);
    created = -1;
    EXPECT_OK(granbond_bond_try_create(m, &k, CREATE_STEP, state, &created),
              "try_create at create_step, outside create_distance");
    CHECK(created == 0, "not created beyond create_distance");
    CHECK(state[i_status] == 0.0, "state still unbonded");
    pair_at(&k, R0_NOMINAL, R_I, R_J);
    created = -1;
    EXPECT_OK(granbond_bond_try_create(m, &k, CREATE_STEP, state, &created),
              "try_create at create_step, within create_distance");
    CHECK(created == 1, "created");
    CHECK(state[i_status] == (double)GB_BOND_STATUS_INTACT, "status slot = GB_BOND_STATUS_INTACT");
    r = distance3(k.x_i, k.x_j);
    CHECK(close_to(state[i_r0], r, 1e-15), say("r0 slot = centre distance %.17g", r));
    memcpy(copy, state, sizeof state);
    created = -1;
    EXPECT_OK(granbond_bond_try_create(m, &k, CREATE_STEP, state, &created), "try_create on an intact bond");
    CHECK(created == 0 && memcmp(copy, state, sizeof state) == 0, "an intact bond is kept as it is");

    /* Stretch: virgin tension Fn = k_fn2 A delta (delta < 0), force on i = Fn n. */
    r0 = state[i_r0];
    pair_at(&k, r0 + stretch, R_I, R_J);
    memset(&out, 0xAB, sizeof out);
    EXPECT_OK(granbond_bond_compute(m, &k, DT, state, &out), "granbond_bond_compute, stretched bond");
    r = distance3(k.x_i, k.x_j);
    for (c = 0; c < 3; c++)
        n[c] = (k.x_i[c] - k.x_j[c]) / r;
    delta = r0 - r;
    rb = LAMBDA * (R_I < R_J ? R_I : R_J);
    area = PI * rb * rb;
    fn = p.k_fn2 * area * delta;
    for (c = 0; c < 3; c++)
        expected[c] = fn * n[c];
    CHECK(delta < 0.0 && close_to(delta, -stretch, 1e-9), say("stretched: delta = r0 - r = %.6g", delta));
    CHECK(close_to(out.delta, delta, 1e-12), say("out.delta = %.17g", delta));
    CHECK(close_to(out.normal_force, fn, 1e-12), say("out.normal_force = k_fn2 A delta = %.17g N", fn));
    CHECK(vec_close(out.force_i, expected, 1e-12),
          say("force on i = Fn n = (%.12g, %.12g, %.12g) to 1e-12", expected[0], expected[1], expected[2]));
    CHECK(dot3(out.force_i, n) < 0.0, "tension pulls i towards j");
    CHECK(close_to(out.sigma, fabs(fn) / area, 1e-12), "out.sigma = |Fn| / A");
    CHECK(fabs(out.tau) < 1e-30, "out.tau = 0 (no shear, no twist)");
    CHECK(norm3(out.torque_i) < 1e-30 && norm3(out.torque_j) < 1e-30, "no torques at rest");
    CHECK(out.status == GB_BOND_STATUS_INTACT && out.break_mode == GB_BREAK_MODE_NONE, "intact, no break");
    CHECK(close_to(state[i_dmin], delta, 1e-12), "delta_min slot = delta");

    /* Squeeze a fresh bond: virgin compression Fn = k_fn1 A sqrt(delta). */
    if (create_bond(m, state))
        return 1;
    r0 = state[i_r0];
    pair_at(&k, r0 - squeeze, R_I, R_J);
    EXPECT_OK(granbond_bond_compute(m, &k, DT, state, &out), "granbond_bond_compute, compressed bond");
    r = distance3(k.x_i, k.x_j);
    for (c = 0; c < 3; c++)
        n[c] = (k.x_i[c] - k.x_j[c]) / r;
    delta = r0 - r;
    fn = p.k_fn1 * area * sqrt(delta);
    for (c = 0; c < 3; c++)
        expected[c] = fn * n[c];
    CHECK(close_to(out.normal_force, fn, 1e-12), say("out.normal_force = k_fn1 A sqrt(delta) = %.17g N", fn));
    CHECK(vec_close(out.force_i, expected, 1e-12), "force on i = Fn n to 1e-12");
    CHECK(dot3(out.force_i, n) > 0.0, "compression pushes i away from j");
    CHECK(close_to(state[i_dmax], delta, 1e-12), "delta_max slot = delta");

    /* dt = 0 is a valid step. */
    EXPECT_OK(granbond_bond_compute(m, &k, 0.0, state, &out), "granbond_bond_compute with dt = 0");

    /* A pair that was never bonded exerts nothing. */
    memset(state, 0, sizeof state);
    EXPECT_OK(granbond_bond_compute(m, &k, DT, state, &out), "granbond_bond_compute on an unbonded pair");
    CHECK(out.status == GB_BOND_STATUS_UNBONDED && vec_zero(out.force_i) && vec_zero(out.torque_i) &&
              vec_zero(out.torque_j),
          "unbonded: status UNBONDED, no force, no torque");

    granbond_bond_model_free(m);
    return 0;
}

static int test_bond_errors(void)
{
    const GbBondParams p = bond_fixture();
    GbBondModel *m = NULL;
    GbPairKinematics good, k;
    GbBondOutput out;
    double state[GRANBOND_BOND_STATE_LEN], copy[GRANBOND_BOND_STATE_LEN];
    union {
        double d[GRANBOND_BOND_STATE_LEN + 1];
        unsigned char bytes[(GRANBOND_BOND_STATE_LEN + 1) * sizeof(double)];
    } misaligned;
    int32_t created = 0;

    if (new_bond_model(&p, &m) || create_bond(m, state))
        return 1;
    memcpy(copy, state, sizeof state);
    pair_at(&good, R0_NOMINAL + 1.0e-6, R_I, R_J);

    /* Bad kinematics on an intact bond: the error, and the state untouched. */
    k = good;
    memcpy(k.x_i, k.x_j, sizeof k.x_i);
    EXPECT(granbond_bond_compute(m, &k, DT, state, &out), GB_STATUS_COINCIDENT_CENTRES, "coincident centres");
    EXPECT_MESSAGE("coincident");
    CHECK(memcmp(copy, state, sizeof state) == 0, "state untouched");
    k = good;
    k.v_i[1] = NAN;
    EXPECT(granbond_bond_compute(m, &k, DT, state, &out), GB_STATUS_NON_FINITE_INPUT, "NaN in v_i");
    CHECK(memcmp(copy, state, sizeof state) == 0, "state untouched");
    k = good;
    k.x_j[2] = INFINITY;
    EXPECT(granbond_bond_compute(m, &k, DT, state, &out), GB_STATUS_NON_FINITE_INPUT, "inf in x_j");
    k = good;
    k.w_j[0] = -INFINITY;
    EXPECT(granbond_bond_compute(m, &k, DT, state, &out), GB_STATUS_NON_FINITE_INPUT, "-inf in w_j");
    k = good;
    k.radius_i = NAN;
    EXPECT(granbond_bond_compute(m, &k, DT, state, &out), GB_STATUS_NON_FINITE_INPUT, "NaN radius_i");
    k = good;
    k.radius_j = 0.0;
    EXPECT(granbond_bond_compute(m, &k, DT, state, &out), GB_STATUS_NON_POSITIVE_RADIUS, "radius_j = 0");
    EXPECT_MESSAGE("radius");
    k = good;
    k.radius_i = -1.0e-3;
    EXPECT(granbond_bond_compute(m, &k, DT, state, &out), GB_STATUS_NON_POSITIVE_RADIUS, "radius_i < 0");
    CHECK(memcmp(copy, state, sizeof state) == 0, "state untouched");
    CHECK(granbond_last_error_parameter() == -1, "no parameter id after an input error");

    /* Bad time steps. */
    EXPECT(granbond_bond_compute(m, &good, -1.0e-9, state, &out), GB_STATUS_INVALID_ARGUMENT, "dt < 0");
    EXPECT_MESSAGE("dt");
    EXPECT(granbond_bond_compute(m, &good, NAN, state, &out), GB_STATUS_INVALID_ARGUMENT, "dt = NaN");
    EXPECT(granbond_bond_compute(m, &good, INFINITY, state, &out), GB_STATUS_INVALID_ARGUMENT, "dt = inf");
    CHECK(memcmp(copy, state, sizeof state) == 0, "state untouched");

    /* Creation from bad kinematics. */
    memset(state, 0, sizeof state);
    k = good;
    memcpy(k.x_j, k.x_i, sizeof k.x_j);
    EXPECT(granbond_bond_try_create(m, &k, CREATE_STEP, state, &created), GB_STATUS_COINCIDENT_CENTRES,
           "try_create, coincident centres");
    k = good;
    k.x_i[0] = NAN;
    EXPECT(granbond_bond_try_create(m, &k, CREATE_STEP, state, &created), GB_STATUS_NON_FINITE_INPUT,
           "try_create, NaN position");
    k = good;
    k.radius_i = 0.0;
    EXPECT(granbond_bond_try_create(m, &k, CREATE_STEP, state, &created), GB_STATUS_NON_POSITIVE_RADIUS,
           "try_create, radius 0");

    /* A misaligned state pointer is refused, not dereferenced. */
    EXPECT(granbond_bond_compute(m, &good, DT, (double *)(void *)(misaligned.bytes + 4), &out),
           GB_STATUS_NULL_POINTER, "granbond_bond_compute with a misaligned state");
    EXPECT_MESSAGE("misaligned");

    /* NULL for each pointer argument. */
    memcpy(state, copy, sizeof state);
    EXPECT_NULL_ARG(granbond_bond_try_create(NULL, &good, CREATE_STEP, state, &created), "granbond_bond_try_create",
                    "model");
    EXPECT_NULL_ARG(granbond_bond_try_create(m, NULL, CREATE_STEP, state, &created), "granbond_bond_try_create",
                    "kinematics");
    EXPECT_NULL_ARG(granbond_bond_try_create(m, &good, CREATE_STEP, NULL, &created), "granbond_bond_try_create",
                    "state");
    EXPECT_NULL_ARG(granbond_bond_try_create(m, &good, CREATE_STEP, state, NULL), "granbond_bond_try_create",
                    "created");
    EXPECT_NULL_ARG(granbond_bond_compute(NULL, &good, DT, state, &out), "granbond_bond_compute", "model");
    EXPECT_NULL_ARG(granbond_bond_compute(m, NULL, DT, state, &out), "granbond_bond_compute", "kinematics");
    EXPECT_NULL_ARG(granbond_bond_compute(m, &good, DT, NULL, &out), "granbond_bond_compute", "state");
    EXPECT_NULL_ARG(granbond_bond_compute(m, &good, DT, state, NULL), "granbond_bond_compute", "out");
    CHECK(memcmp(copy, state, sizeof state) == 0, "state untouched by the failed calls");

    granbond_bond_model_free(m);
    return 0;
}

#define N_BATCH 4

static int test_bond_batch(void)
{
    const GbBondParams p = bond_fixture();
    GbBondModel *m = NULL;
    GbPairKinematics k[N_BATCH];
    GbBondOutput out[N_BATCH], single;
    double states[N_BATCH * GRANBOND_BOND_STATE_LEN], before[N_BATCH * GRANBOND_BOND_STATE_LEN];
    double one[GRANBOND_BOND_STATE_LEN], saved;
    size_t failed = 999;
    int b;

    if (new_bond_model(&p, &m))
        return 1;
    for (b = 0; b < N_BATCH; b++) {
        if (create_bond(m, states + b * GRANBOND_BOND_STATE_LEN))
            return 1;
        pair_at(&k[b], R0_NOMINAL + (b - 1.5) * 2.0e-6, R_I, R_J);
        k[b].v_i[0] = 1.0e-3 * b;
        k[b].w_j[2] = 0.5 * b;
    }
    memcpy(before, states, sizeof states);

    /* One bad entry: stops there and reports its index. */
    saved = k[2].x_i[1];
    k[2].x_i[1] = NAN;
    memset(out, 0, sizeof out);
    out[3].status = -7;
    EXPECT(granbond_bond_compute_batch(m, N_BATCH, k, DT, states, out, &failed), GB_STATUS_NON_FINITE_INPUT,
           "granbond_bond_compute_batch with NaN in bond 2");
    CHECK(failed == 2, say("failed_index = 2 (got %u)", (unsigned)failed));
    EXPECT_MESSAGE("bond 2");
    CHECK(out[0].status == GB_BOND_STATUS_INTACT && out[1].status == GB_BOND_STATUS_INTACT,
          "bonds before the bad one were computed");
    CHECK(out[3].status == -7 &&
              memcmp(states + 3 * GRANBOND_BOND_STATE_LEN, before + 3 * GRANBOND_BOND_STATE_LEN,
                     GRANBOND_BOND_STATE_LEN * sizeof(double)) == 0,
          "bonds after the bad one were not touched");
    EXPECT(granbond_bond_compute_batch(m, N_BATCH, k, DT, states, out, NULL), GB_STATUS_NON_FINITE_INPUT,
           "the same batch with failed_index = NULL");
    k[2].x_i[1] = saved;

    /* All good: same results as one call per bond. */
    memcpy(states, before, sizeof states);
    failed = 999;
    EXPECT_OK(granbond_bond_compute_batch(m, N_BATCH, k, DT, states, out, &failed), "granbond_bond_compute_batch");
    CHECK(failed == 999, "failed_index left alone on success");
    for (b = 0; b < N_BATCH; b++) {
        memcpy(one, before + b * GRANBOND_BOND_STATE_LEN, sizeof one);
        EXPECT_OK(granbond_bond_compute(m, &k[b], DT, one, &single), say("granbond_bond_compute, bond %d", b));
        CHECK(vec_close(out[b].force_i, single.force_i, 1e-15) && vec_close(out[b].torque_i, single.torque_i, 1e-15) &&
                  vec_close(out[b].torque_j, single.torque_j, 1e-15) &&
                  memcmp(one, states + b * GRANBOND_BOND_STATE_LEN, sizeof one) == 0,
              say("batch bond %d = single call", b));
    }

    /* Bad dt, empty batch, NULL arguments. */
    failed = 999;
    EXPECT(granbond_bond_compute_batch(m, N_BATCH, k, -DT, states, out, &failed), GB_STATUS_INVALID_ARGUMENT,
           "granbond_bond_compute_batch with dt < 0");
    CHECK(failed == 999, "failed_index not set for a bad dt");
    EXPECT_OK(granbond_bond_compute_batch(m, 0, NULL, DT, NULL, NULL, NULL),
              "granbond_bond_compute_batch, count = 0 and NULL arrays");
    EXPECT_NULL_ARG(granbond_bond_compute_batch(NULL, N_BATCH, k, DT, states, out, &failed),
                    "granbond_bond_compute_batch", "model");
    EXPECT_NULL_ARG(granbond_bond_compute_batch(m, N_BATCH, NULL, DT, states, out, &failed),
                    "granbond_bond_compute_batch", "kinematics");
    EXPECT_NULL_ARG(granbond_bond_compute_batch(m, N_BATCH, k, DT, NULL, out, &failed),
                    "granbond_bond_compute_batch", "states");
    EXPECT_NULL_ARG(granbond_bond_compute_batch(m, N_BATCH, k, DT, states, NULL, &failed),
                    "granbond_bond_compute_batch", "out");

    granbond_bond_model_free(m);
    return 0;
}

#define N_SCATTERED 11

/* States apart in memory, in an order unrelated to their addresses, as in an
 * engine's contact history; among them a broken bond and one that breaks in
 * this step. */
static int scattered_fixture(GbBondModel *m, GbPairKinematics *k, double *memory, double **states)
{
    int b;
    for (b = 0; b < N_SCATTERED; b++) {
        states[b] = memory + 2 * (N_SCATTERED - 1 - b) * GRANBOND_BOND_STATE_LEN;
        if (create_bond(m, states[b]))
            return 1;
        pair_at(&k[b], R0_NOMINAL + (b - 5.0) * 1.0e-6, R_I, R_J);
        k[b].v_i[1] = 2.0e-3 * b;
        k[b].w_i[0] = 0.3 * b;
        k[b].w_j[2] = -0.5 * b;
    }
    states[5][0] = GB_BOND_STATUS_BROKEN;
    pair_at(&k[7], 1.01 * MAX_DISTANCE, R_I, R_J);
    return 0;
}

/* The scattered bonds with their spheres in per-atom arrays, as an engine
 * keeps them: bond b joins atoms 2N-1-b (i) and b (j). */
static void indexed_fixture(const GbPairKinematics *k, double *x, double *v, double *w, double *radius,
                            int32_t *pairs, GbAtomArrays *atoms)
{
    int b, c;
    for (b = 0; b < N_SCATTERED; b++) {
        const int i = 2 * N_SCATTERED - 1 - b, j = b;
        pairs[2 * b] = i;
        pairs[2 * b + 1] = j;
        for (c = 0; c < 3; c++) {
            x[3 * i + c] = k[b].x_i[c];
            v[3 * i + c] = k[b].v_i[c];
            w[3 * i + c] = k[b].w_i[c];
            x[3 * j + c] = k[b].x_j[c];
            v[3 * j + c] = k[b].v_j[c];
            w[3 * j + c] = k[b].w_j[c];
        }
        radius[i] = k[b].radius_i;
        radius[j] = k[b].radius_j;
    }
    atoms->x = x;
    atoms->v = v;
    atoms->omega = w;
    atoms->radius = radius;
    atoms->count = 2 * N_SCATTERED;
}

/* Each bond as one granbond_bond_compute would give it, bit for bit; a bad
 * state pointer or bond is reported with its index. */
static int test_bond_indexed_results(void)
{
    const GbBondParams p = bond_fixture();
    GbBondModel *m = NULL;
    GbPairKinematics k[N_SCATTERED];
    GbBondOutput out[N_SCATTERED], single;
    double memory[2 * N_SCATTERED * GRANBOND_BOND_STATE_LEN], before[sizeof memory / sizeof(double)];
    double x[6 * N_SCATTERED], v[6 * N_SCATTERED], w[6 * N_SCATTERED], radius[2 * N_SCATTERED];
    double *states[N_SCATTERED], one[GRANBOND_BOND_STATE_LEN], *saved;
    int32_t pairs[2 * N_SCATTERED];
    GbAtomArrays atoms;
    size_t failed = 999;
    int b;

    if (new_bond_model(&p, &m) || scattered_fixture(m, k, memory, states))
        return 1;
    indexed_fixture(k, x, v, w, radius, pairs, &atoms);
    memcpy(before, memory, sizeof memory);

    EXPECT_OK(granbond_bond_compute_indexed(m, N_SCATTERED, &atoms, pairs, DT, states, out, &failed),
              "granbond_bond_compute_indexed");
    CHECK(failed == 999, "failed_index left alone on success");
    CHECK(out[5].status == GB_BOND_STATUS_BROKEN && out[7].status == GB_BOND_STATUS_BROKEN &&
              out[7].break_mode == GB_BREAK_MODE_DISTANCE && out[3].status == GB_BOND_STATUS_INTACT,
          "indexed: broken, breaking and intact bonds");
    for (b = 0; b < N_SCATTERED; b++) {
        memcpy(one, before + (states[b] - memory), sizeof one);
        EXPECT_OK(granbond_bond_compute(m, &k[b], DT, one, &single), say("granbond_bond_compute, bond %d", b));
        CHECK(memcmp(&out[b], &single, sizeof single) == 0 && memcmp(one, states[b], sizeof one) == 0,
              say("indexed bond %d = single call, bit for bit", b));
    }

    /* A null state pointer: reported with its index before any bond moves. */
    memcpy(memory, before, sizeof memory);
    saved = states[4];
    states[4] = NULL;
    EXPECT(granbond_bond_compute_indexed(m, N_SCATTERED, &atoms, pairs, DT, states, out, &failed),
           GB_STATUS_NULL_POINTER, "granbond_bond_compute_indexed with states[4] = NULL");
    CHECK(failed == 4, say("failed_index = 4 (got %u)", (unsigned)failed));
    EXPECT_MESSAGE("bond 4");
    CHECK(memcmp(memory, before, sizeof memory) == 0, "no state advanced when a state pointer is null");
    states[4] = saved;

    /* A bad bond stops there, as in the batch call: v_j of bond 6 is atom 6's. */
    v[3 * 6 + 2] = INFINITY;
    EXPECT(granbond_bond_compute_indexed(m, N_SCATTERED, &atoms, pairs, DT, states, out, &failed),
           GB_STATUS_NON_FINITE_INPUT, "granbond_bond_compute_indexed with inf in bond 6");
    CHECK(failed == 6, say("failed_index = 6 (got %u)", (unsigned)failed));
    v[3 * 6 + 2] = 0.0;

    EXPECT(granbond_bond_compute_indexed(m, N_SCATTERED, &atoms, pairs, NAN, states, out, NULL),
           GB_STATUS_INVALID_ARGUMENT, "granbond_bond_compute_indexed with dt = NaN");

    granbond_bond_model_free(m);
    return 0;
}

/* An index outside the arrays is refused before any bond moves. */
static int test_bond_indexed(void)
{
    const GbBondParams p = bond_fixture();
    GbBondModel *m = NULL;
    GbPairKinematics k[N_SCATTERED];
    GbBondOutput out[N_SCATTERED], want[N_SCATTERED];
    double memory[2 * N_SCATTERED * GRANBOND_BOND_STATE_LEN], before[sizeof memory / sizeof(double)],
        after[sizeof memory / sizeof(double)];
    double x[6 * N_SCATTERED], v[6 * N_SCATTERED], w[6 * N_SCATTERED], radius[2 * N_SCATTERED];
    double *states[N_SCATTERED];
    int32_t pairs[2 * N_SCATTERED];
    GbAtomArrays atoms, bad;
    size_t failed = 999;
    int b;

    if (new_bond_model(&p, &m) || scattered_fixture(m, k, memory, states))
        return 1;
    indexed_fixture(k, x, v, w, radius, pairs, &atoms);
    memcpy(before, memory, sizeof memory);

    for (b = 0; b < N_SCATTERED; b++)
        EXPECT_OK(granbond_bond_compute(m, &k[b], DT, states[b], &want[b]),
                  say("granbond_bond_compute, bond %d (reference for the indexed call)", b));
    memcpy(after, memory, sizeof memory);
    memcpy(memory, before, sizeof memory);
    EXPECT_OK(granbond_bond_compute_indexed(m, N_SCATTERED, &atoms, pairs, DT, states, out, &failed),
              "granbond_bond_compute_indexed");
    CHECK(failed == 999, "failed_index left alone on success");
    CHECK(memcmp(out, want, sizeof out) == 0 && memcmp(memory, after, sizeof memory) == 0,
          "indexed = single calls, outputs and states bit for bit");

    /* An atom index past the arrays, or negative: its bond, nothing moved. */
    memcpy(memory, before, sizeof memory);
    pairs[2 * 3 + 1] = 2 * N_SCATTERED;
    EXPECT(granbond_bond_compute_indexed(m, N_SCATTERED, &atoms, pairs, DT, states, out, &failed),
           GB_STATUS_INVALID_ARGUMENT, "granbond_bond_compute_indexed with an index = count");
    CHECK(failed == 3, say("failed_index = 3 (got %u)", (unsigned)failed));
    EXPECT_MESSAGE("bond 3");
    EXPECT_MESSAGE("atom index 22");
    CHECK(memcmp(memory, before, sizeof memory) == 0, "no state advanced for a bad index");
    pairs[2 * 3 + 1] = 3;
    pairs[2 * 8] = -1;
    EXPECT(granbond_bond_compute_indexed(m, N_SCATTERED, &atoms, pairs, DT, states, out, &failed),
           GB_STATUS_INVALID_ARGUMENT, "granbond_bond_compute_indexed with a negative index");
    CHECK(failed == 8, say("failed_index = 8 (got %u)", (unsigned)failed));
    pairs[2 * 8] = 2 * N_SCATTERED - 1 - 8;

    /* count too large for the arrays' sizes to be computed */
    bad = atoms;
    bad.count = (size_t)-1;
    EXPECT(granbond_bond_compute_indexed(m, N_SCATTERED, &bad, pairs, DT, states, out, &failed),
           GB_STATUS_INVALID_ARGUMENT, "granbond_bond_compute_indexed with atoms->count = SIZE_MAX");
    EXPECT_MESSAGE("atoms->count");

    EXPECT_OK(granbond_bond_compute_indexed(m, 0, &atoms, NULL, DT, NULL, NULL, NULL),
              "granbond_bond_compute_indexed, count = 0 and NULL arrays");
    EXPECT(granbond_bond_compute_indexed(m, N_SCATTERED, &atoms, pairs, -DT, states, out, NULL),
           GB_STATUS_INVALID_ARGUMENT, "granbond_bond_compute_indexed with dt < 0");
    EXPECT_NULL_ARG(granbond_bond_compute_indexed(NULL, N_SCATTERED, &atoms, pairs, DT, states, out, &failed),
                    "granbond_bond_compute_indexed", "model");
    EXPECT_NULL_ARG(granbond_bond_compute_indexed(m, N_SCATTERED, NULL, pairs, DT, states, out, &failed),
                    "granbond_bond_compute_indexed", "atoms");
    EXPECT_NULL_ARG(granbond_bond_compute_indexed(m, N_SCATTERED, &atoms, NULL, DT, states, out, &failed),
                    "granbond_bond_compute_indexed", "pairs");
    EXPECT_NULL_ARG(granbond_bond_compute_indexed(m, N_SCATTERED, &atoms, pairs, DT, NULL, out, &failed),
                    "granbond_bond_compute_indexed", "states");
    EXPECT_NULL_ARG(granbond_bond_compute_indexed(m, N_SCATTERED, &atoms, pairs, DT, states, NULL, &failed),
                    "granbond_bond_compute_indexed", "out");
    bad = atoms;
    bad.x = NULL;
    EXPECT_NULL_ARG(granbond_bond_compute_indexed(m, N_SCATTERED, &bad, pairs, DT, states, out, &failed),
                    "granbond_bond_compute_indexed", "atoms->x");
    bad = atoms;
    bad.omega = NULL;
    EXPECT_NULL_ARG(granbond_bond_compute_indexed(m, N_SCATTERED, &bad, pairs, DT, states, out, &failed),
                    "granbond_bond_compute_indexed", "atoms->omega");
    bad = atoms;
    bad.radius = NULL;
    EXPECT_NULL_ARG(granbond_bond_compute_indexed(m, N_SCATTERED, &bad, pairs, DT, states, out, &failed),
                    "granbond_bond_compute_indexed", "atoms->radius");

    granbond_bond_model_free(m);
    return 0;
}

static int test_bond_break(void)
{
    GbBondParams p = bond_fixture();
    GbBondModel *m = NULL, *always = NULL, *stress = NULL;
    GbPairKinematics k;
    GbBondOutput out;
    double state[GRANBOND_BOND_STATE_LEN];
    static const double distances[6] = {1.85e-3, 1.95e-3, 1.85e-3, 1.95e-3, 1.8e-3, 2.5e-3};
    int s, breaks = 0, i_status;
    int32_t created = -1;

    if (new_bond_model(&p, &m) || create_bond(m, state))
        return 1;
    i_status = slot_index(GB_STATE_KIND_BOND, "status");

    /* Distance mode: breaks in the first step with r > max_distance, once. */
    for (s = 0; s < 6; s++) {
        pair_at(&k, distances[s], R_I, R_J);
        memset(&out, 0xAB, sizeof out);
        EXPECT_OK(granbond_bond_compute(m, &k, DT, state, &out), say("step %d at r = %g", s, distances[s]));
        if (out.break_mode == GB_BREAK_MODE_DISTANCE)
            breaks++;
        if (s == 0)
            CHECK(out.status == GB_BOND_STATUS_INTACT && out.break_mode == GB_BREAK_MODE_NONE &&
                      !vec_zero(out.force_i),
                  "r < max_distance: intact, loaded");
        if (s == 1) {
            CHECK(out.break_mode == GB_BREAK_MODE_DISTANCE, "r > max_distance: break_mode = GB_BREAK_MODE_DISTANCE");
            CHECK(out.status == GB_BOND_STATUS_BROKEN, "status = GB_BOND_STATUS_BROKEN");
            CHECK(state[i_status] == (double)GB_BOND_STATUS_BROKEN, "status slot = GB_BOND_STATUS_BROKEN");
        }
        if (s >= 1)
            CHECK(out.status == GB_BOND_STATUS_BROKEN && vec_zero(out.force_i) && vec_zero(out.torque_i) &&
                      vec_zero(out.torque_j),
                  say("step %d: broken, no force, no torque", s));
        if (s >= 2)
            CHECK(out.break_mode == GB_BREAK_MODE_NONE, say("step %d: break_mode = NONE after the break", s));
    }
    CHECK(breaks == 1, "the bond broke exactly once");

    /* A broken bond is re-created only under create_always. */
    pair_at(&k, R0_NOMINAL, R_I, R_J);
    EXPECT_OK(granbond_bond_try_create(m, &k, CREATE_STEP, state, &created), "try_create on a broken bond");
    CHECK(created == 0 && state[i_status] == (double)GB_BOND_STATUS_BROKEN, "broken bond stays broken");
    p.create_always = 1;
    if (new_bond_model(&p, &always))
        return 1;
    created = -1;
    EXPECT_OK(granbond_bond_try_create(always, &k, 12345, state, &created),
              "try_create on a broken bond, create_always on");
    CHECK(created == 1 && state[i_status] == (double)GB_BOND_STATUS_INTACT, "re-created under create_always");

    /* Stress mode: tension breaks at sigma = k_fn2 |delta| >= max_sigma. */
    p = bond_fixture();
    p.stress_break = 1;
    p.max_sigma = 1.0e5; /* Pa: k_fn2 * 1e-5 m */
    if (new_bond_model(&p, &stress) || create_bond(stress, state))
        return 1;
    pair_at(&k, state[slot_index(GB_STATE_KIND_BOND, "r0")] + 0.5e-5, R_I, R_J);
    EXPECT_OK(granbond_bond_compute(stress, &k, DT, state, &out), "stress mode, sigma below max_sigma");
    CHECK(out.status == GB_BOND_STATUS_INTACT && out.sigma < p.max_sigma, "intact below the limit");
    pair_at(&k, state[slot_index(GB_STATE_KIND_BOND, "r0")] + 2.0e-5, R_I, R_J);
    EXPECT_OK(granbond_bond_compute(stress, &k, DT, state, &out), "stress mode, sigma above max_sigma");
    CHECK(out.status == GB_BOND_STATUS_BROKEN && out.break_mode == GB_BREAK_MODE_TENSION && vec_zero(out.force_i),
          "breaks in tension: break_mode = GB_BREAK_MODE_TENSION, no force");

    granbond_bond_model_free(stress);
    granbond_bond_model_free(always);
    granbond_bond_model_free(m);
    return 0;
}

/* ------------------------------------------------------------------------ */
/* Wall bonds                                                                */
/* ------------------------------------------------------------------------ */

#define R_W 0.9e-3

static int test_wall_bond(void)
{
    const GbBondParams p = bond_fixture();
    GbBondModel *m = NULL;
    GbSphereKinematics sphere, bad;
    GbBondOutput out;
    double state[GRANBOND_WALL_BOND_STATE_LEN], copy[GRANBOND_WALL_BOND_STATE_LEN];
    double contact[3] = {0.2e-3, -0.1e-3, 0.0};
    double wall_velocity[3] = {0.0, 0.0, 0.0};
    double partner[3], n[3], expected[3], r0, r, delta, area, fn;
    const double stretch = 1.0e-5, dt = 1.0e-6;
    int32_t created = -1;
    int c, i_partner, i_r0;

    if (new_bond_model(&p, &m))
        return 1;
    i_partner = slot_index(GB_STATE_KIND_WALL_BOND, "partner_x");
    i_r0 = slot_index(GB_STATE_KIND_WALL_BOND, "r0");
    CHECK(i_partner == GRANBOND_BOND_STATE_LEN && i_r0 >= 0, "wall bond slots partner_x, r0 found");
    memset(state, 0, sizeof state);
    memset(&sphere, 0, sizeof sphere);

    /* Too far from the contact point: no bond. */
    sphere.x[0] = contact[0];
    sphere.x[1] = contact[1];
    sphere.x[2] = 2.0 * R_W;
    sphere.radius = R_W;
    EXPECT_OK(granbond_wall_bond_try_create(m, &sphere, contact, CREATE_STEP, state, &created),
              "granbond_wall_bond_try_create, sphere off the wall");
    CHECK(created == 0, "not created outside create_distance");

    /* Touching the wall at the contact point: bonded to a mirror sphere. */
    sphere.x[2] = R_W;
    created = -1;
    EXPECT_OK(granbond_wall_bond_try_create(m, &sphere, contact, CREATE_STEP - 1, state, &created),
              "granbond_wall_bond_try_create, before create_step");
    CHECK(created == 0, "not created before create_step");
    EXPECT_OK(granbond_wall_bond_try_create(m, &sphere, contact, CREATE_STEP, state, &created),
              "granbond_wall_bond_try_create, touching, at create_step");
    CHECK(created == 1, "wall bond created");
    CHECK(state[0] == (double)GB_BOND_STATUS_INTACT, "status slot = INTACT");
    for (c = 0; c < 3; c++)
        partner[c] = state[i_partner + c];
    CHECK(fabs(partner[0] - contact[0]) < 1e-18 && fabs(partner[1] - contact[1]) < 1e-18 &&
              close_to(partner[2], -R_W, 1e-15),
          "partner centre = contact point - R n (the sphere's mirror image)");
    CHECK(close_to(state[i_r0], 2.0 * R_W, 1e-15), "r0 = 2 R");

    /* Pull the sphere off the wall: tension along the wall normal. */
    r0 = state[i_r0];
    sphere.x[2] = R_W + stretch;
    EXPECT_OK(granbond_wall_bond_compute(m, &sphere, wall_velocity, dt, state, &out),
              "granbond_wall_bond_compute, sphere pulled off the wall");
    r = distance3(sphere.x, partner);
    for (c = 0; c < 3; c++)
        n[c] = (sphere.x[c] - partner[c]) / r;
    delta = r0 - r;
    area = PI * (LAMBDA * R_W) * (LAMBDA * R_W);
    fn = p.k_fn2 * area * delta;
    for (c = 0; c < 3; c++)
        expected[c] = fn * n[c];
    CHECK(close_to(out.normal_force, fn, 1e-12), say("wall bond Fn = k_fn2 A delta = %.17g N", fn));
    CHECK(vec_close(out.force_i, expected, 1e-12) && out.force_i[2] < 0.0,
          "force on the sphere = Fn n, towards the wall");
    CHECK(out.status == GB_BOND_STATUS_INTACT, "intact");

    /* A moving wall carries the partner centre with it. */
    wall_velocity[0] = 1.0e-3;
    EXPECT_OK(granbond_wall_bond_compute(m, &sphere, wall_velocity, dt, state, &out),
              "granbond_wall_bond_compute, wall moving along x");
    CHECK(fabs(state[i_partner] - (partner[0] + wall_velocity[0] * dt)) < 1e-18 &&
              state[i_partner + 1] == partner[1] && state[i_partner + 2] == partner[2],
          "partner centre moved by wall_velocity dt");
    CHECK(out.status == GB_BOND_STATUS_INTACT && isfinite(out.force_i[0]), "intact, finite force");

    /* Errors. */
    memcpy(copy, state, sizeof state);
    wall_velocity[1] = NAN;
    EXPECT(granbond_wall_bond_compute(m, &sphere, wall_velocity, dt, state, &out), GB_STATUS_NON_FINITE_INPUT,
           "granbond_wall_bond_compute, NaN wall velocity");
    CHECK(memcmp(copy, state, sizeof state) == 0, "state untouched");
    wall_velocity[1] = 0.0;
    bad = sphere;
    bad.radius = 0.0;
    EXPECT(granbond_wall_bond_compute(m, &bad, wall_velocity, dt, state, &out), GB_STATUS_NON_POSITIVE_RADIUS,
           "granbond_wall_bond_compute, radius 0");
    EXPECT(granbond_wall_bond_compute(m, &sphere, wall_velocity, -dt, state, &out), GB_STATUS_INVALID_ARGUMENT,
           "granbond_wall_bond_compute, dt < 0");
    bad = sphere;
    bad.x[0] = INFINITY;
    {
        /* Kinematics are checked when creation is possible (an intact bond
         * returns at once: its compute call checks them). */
        double fresh[GRANBOND_WALL_BOND_STATE_LEN] = {0};
        EXPECT(granbond_wall_bond_try_create(m, &bad, contact, CREATE_STEP, fresh, &created),
               GB_STATUS_NON_FINITE_INPUT, "granbond_wall_bond_try_create, inf position");
        EXPECT_OK(granbond_wall_bond_try_create(m, &bad, contact, CREATE_STEP, state, &created),
                  "granbond_wall_bond_try_create on an intact bond returns before the kinematics");
        CHECK(created == 0, "an intact wall bond is kept");
    }
    bad = sphere;
    bad.radius = -R_W;
    {
        double fresh[GRANBOND_WALL_BOND_STATE_LEN] = {0};
        EXPECT(granbond_wall_bond_try_create(m, &bad, contact, CREATE_STEP, fresh, &created),
               GB_STATUS_NON_POSITIVE_RADIUS, "granbond_wall_bond_try_create, negative radius");
    }
    CHECK(memcmp(copy, state, sizeof state) == 0, "state untouched");

    EXPECT_NULL_ARG(granbond_wall_bond_try_create(NULL, &sphere, contact, CREATE_STEP, state, &created),
                    "granbond_wall_bond_try_create", "model");
    EXPECT_NULL_ARG(granbond_wall_bond_try_create(m, NULL, contact, CREATE_STEP, state, &created),
                    "granbond_wall_bond_try_create", "sphere");
    EXPECT_NULL_ARG(granbond_wall_bond_try_create(m, &sphere, NULL, CREATE_STEP, state, &created),
                    "granbond_wall_bond_try_create", "contact_point");
    EXPECT_NULL_ARG(granbond_wall_bond_try_create(m, &sphere, contact, CREATE_STEP, NULL, &created),
                    "granbond_wall_bond_try_create", "state");
    EXPECT_NULL_ARG(granbond_wall_bond_try_create(m, &sphere, contact, CREATE_STEP, state, NULL),
                    "granbond_wall_bond_try_create", "created");
    EXPECT_NULL_ARG(granbond_wall_bond_compute(NULL, &sphere, wall_velocity, dt, state, &out),
                    "granbond_wall_bond_compute", "model");
    EXPECT_NULL_ARG(granbond_wall_bond_compute(m, NULL, wall_velocity, dt, state, &out),
                    "granbond_wall_bond_compute", "sphere");
    EXPECT_NULL_ARG(granbond_wall_bond_compute(m, &sphere, NULL, dt, state, &out), "granbond_wall_bond_compute",
                    "wall_velocity");
    EXPECT_NULL_ARG(granbond_wall_bond_compute(m, &sphere, wall_velocity, dt, NULL, &out),
                    "granbond_wall_bond_compute", "state");
    EXPECT_NULL_ARG(granbond_wall_bond_compute(m, &sphere, wall_velocity, dt, state, NULL),
                    "granbond_wall_bond_compute", "out");
    CHECK(memcmp(copy, state, sizeof state) == 0, "state untouched by the failed calls");

    granbond_bond_model_free(m);
    return 0;
}

/* ------------------------------------------------------------------------ */
/* Bond neighbour range and time step                                        */
/* ------------------------------------------------------------------------ */

static int test_bond_limits(void)
{
    GbBondParams p = bond_fixture();
    GbBondModel *m = NULL, *stress = NULL, *unbreakable = NULL;
    const double mass_i = 1.0e-5, mass_j = 0.6e-5;
    double d = -1.0, dt = -1.0, m_eff, rb, area, bound;

    if (new_bond_model(&p, &m))
        return 1;
    EXPECT_OK(granbond_bond_max_distance(m, R0_NOMINAL, &d), "granbond_bond_max_distance, distance mode");
    EXPECT(granbond_bond_max_distance(m, NAN, &d), GB_STATUS_INVALID_ARGUMENT, "granbond_bond_max_distance, NaN r0");
    EXPECT(granbond_bond_max_distance(m, -1.0, &d), GB_STATUS_INVALID_ARGUMENT, "granbond_bond_max_distance, r0 < 0");
    CHECK(d == MAX_DISTANCE, "distance mode: max bond distance = max_distance");

    p.stress_break = 1;
    p.max_sigma = 1.0e7;
    p.use_ratio = 1;
    p.tension_compression_ratio = 0.5;
    if (new_bond_model(&p, &stress))
        return 1;
    EXPECT_OK(granbond_bond_max_distance(stress, R0_NOMINAL, &d), "granbond_bond_max_distance, stress mode");
    CHECK(close_to(d, R0_NOMINAL + 0.5 * 1.0e7 / p.k_fn2, 1e-14),
          say("stress mode: r0 + gamma max_sigma / k_fn2 = %.17g", R0_NOMINAL + 0.5 * 1.0e7 / p.k_fn2));
    p.max_sigma = INFINITY;
    if (new_bond_model(&p, &unbreakable))
        return 1;
    EXPECT_OK(granbond_bond_max_distance(unbreakable, R0_NOMINAL, &d),
              "granbond_bond_max_distance, stress mode without limit");
    CHECK(isinf(d) && d > 0.0, "never breaks: +inf");
    EXPECT_NULL_ARG(granbond_bond_max_distance(NULL, R0_NOMINAL, &d), "granbond_bond_max_distance", "model");
    EXPECT_NULL_ARG(granbond_bond_max_distance(m, R0_NOMINAL, NULL), "granbond_bond_max_distance", "out");

    /* Neighbour-list factor: 1.1 x the largest bonded distance / (2 min R), at least 1. */
    EXPECT_OK(granbond_bond_contact_distance_factor(m, R_J, &d),
              "granbond_bond_contact_distance_factor, distance mode");
    CHECK(close_to(d, 1.1 * MAX_DISTANCE / (2.0 * R_J), 1e-14),
          say("distance mode: 1.1 max_distance / (2 R_min) = %.17g", 1.1 * MAX_DISTANCE / (2.0 * R_J)));
    EXPECT_OK(granbond_bond_contact_distance_factor(stress, R_J, &d),
              "granbond_bond_contact_distance_factor, stress mode");
    CHECK(close_to(d, 1.1 * (CREATE_DISTANCE + 0.5 * 1.0e7 / p.k_fn2) / (2.0 * R_J), 1e-14),
          "stress mode: 1.1 (create_distance + gamma max_sigma / k_fn2) / (2 R_min)");
    EXPECT_OK(granbond_bond_contact_distance_factor(unbreakable, R_J, &d),
              "granbond_bond_contact_distance_factor, stress mode without limit");
    CHECK(isinf(d) && d > 0.0, "unlimited stretch: +inf");
    EXPECT_OK(granbond_bond_contact_distance_factor(m, 1.0, &d),
              "granbond_bond_contact_distance_factor, huge spheres");
    CHECK(d == 1.0, "never below 1");
    EXPECT(granbond_bond_contact_distance_factor(m, 0.0, &d), GB_STATUS_INVALID_ARGUMENT,
           "granbond_bond_contact_distance_factor, min_radius = 0");
    EXPECT_MESSAGE("min_radius");
    EXPECT(granbond_bond_contact_distance_factor(m, NAN, &d), GB_STATUS_INVALID_ARGUMENT,
           "granbond_bond_contact_distance_factor, min_radius = NaN");
    EXPECT(granbond_bond_contact_distance_factor(m, INFINITY, &d), GB_STATUS_INVALID_ARGUMENT,
           "granbond_bond_contact_distance_factor, min_radius = inf");
    EXPECT_NULL_ARG(granbond_bond_contact_distance_factor(NULL, R_J, &d), "granbond_bond_contact_distance_factor",
                    "model");
    EXPECT_NULL_ARG(granbond_bond_contact_distance_factor(m, R_J, NULL), "granbond_bond_contact_distance_factor",
                    "out");

    EXPECT_OK(granbond_bond_critical_timestep(m, R_I, R_J, mass_i, mass_j, &dt), "granbond_bond_critical_timestep");
    m_eff = mass_i * mass_j / (mass_i + mass_j);
    rb = LAMBDA * R_J;
    area = PI * rb * rb;
    bound = 2.0 * sqrt(m_eff / (p.k_fn2 * area));
    CHECK(isfinite(dt) && dt > 0.0, say("critical time step %.6g s is positive and finite", dt));
    CHECK(dt <= bound * (1.0 + 1e-12), say("critical time step <= 2 sqrt(m_eff / (k_fn2 A)) = %.6g s", bound));
    EXPECT(granbond_bond_critical_timestep(m, R_I, R_J, 0.0, mass_j, &dt), GB_STATUS_INVALID_ARGUMENT,
           "granbond_bond_critical_timestep, mass_i = 0");
    EXPECT_MESSAGE("mass_i");
    EXPECT(granbond_bond_critical_timestep(m, R_I, R_J, mass_i, -1.0, &dt), GB_STATUS_INVALID_ARGUMENT,
           "granbond_bond_critical_timestep, mass_j < 0");
    EXPECT_MESSAGE("mass_j");
    EXPECT(granbond_bond_critical_timestep(m, R_I, R_J, NAN, mass_j, &dt), GB_STATUS_INVALID_ARGUMENT,
           "granbond_bond_critical_timestep, mass_i = NaN");
    EXPECT(granbond_bond_critical_timestep(m, 0.0, R_J, mass_i, mass_j, &dt), GB_STATUS_INVALID_ARGUMENT,
           "granbond_bond_critical_timestep, radius_i = 0");
    EXPECT_MESSAGE("radius_i");
    EXPECT(granbond_bond_critical_timestep(m, R_I, INFINITY, mass_i, mass_j, &dt), GB_STATUS_INVALID_ARGUMENT,
           "granbond_bond_critical_timestep, radius_j = inf");
    EXPECT_NULL_ARG(granbond_bond_critical_timestep(NULL, R_I, R_J, mass_i, mass_j, &dt),
                    "granbond_bond_critical_timestep", "model");
    EXPECT_NULL_ARG(granbond_bond_critical_timestep(m, R_I, R_J, mass_i, mass_j, NULL),
                    "granbond_bond_critical_timestep", "out");

    {
        double recommended = 0.0;
        EXPECT_OK(granbond_bond_critical_timestep(m, R_I, R_J, mass_i, mass_j, &dt),
                  "granbond_bond_critical_timestep");
        EXPECT_OK(granbond_bond_recommended_timestep(m, R_I, R_J, mass_i, mass_j, &recommended),
                  "granbond_bond_recommended_timestep");
        CHECK(recommended > 0.0 && recommended < dt,
              say("recommended step %.6g s is below the critical step %.6g s", recommended, dt));
        EXPECT(granbond_bond_recommended_timestep(m, R_I, R_J, 0.0, mass_j, &recommended),
               GB_STATUS_INVALID_ARGUMENT, "granbond_bond_recommended_timestep, mass_i = 0");
        EXPECT_MESSAGE("mass_i");
        EXPECT_NULL_ARG(granbond_bond_recommended_timestep(NULL, R_I, R_J, mass_i, mass_j, &recommended),
                        "granbond_bond_recommended_timestep", "model");
        EXPECT_NULL_ARG(granbond_bond_recommended_timestep(m, R_I, R_J, mass_i, mass_j, NULL),
                        "granbond_bond_recommended_timestep", "out");
    }

    granbond_bond_model_free(unbreakable);
    granbond_bond_model_free(stress);
    granbond_bond_model_free(m);
    return 0;
}

/* ------------------------------------------------------------------------ */
/* Run checks: time step and creation rules over the atom types present      */
/* ------------------------------------------------------------------------ */

static int test_run_checks(void)
{
    GbBondParams p;
    GbVoigtParams vp;
    GbBondModel *bond = NULL;
    GbVoigtModel *voigt = NULL;
    GbCheckReport report;
    GbTypeBodies bodies[3];
    const GbBondModel *bonds[9] = {0};
    const GbVoigtModel *voigts[9] = {0};
    double critical = 0.0, mass = 2500.0 * 4.0 / 3.0 * PI * 1e-9;
    int t;
    granbond_bond_params_default(&p);
    p.k_fn1 = p.ku_fn1 = p.kc_fn1 = 1e9;
    p.k_fn2 = p.ku_fn2 = p.kc_fn2 = 1e9;
    p.create_distance = 2.2e-3;
    p.max_distance = 2.08e-3;
    p.create_step = 1;
    p.create_always = 1;
    EXPECT_OK(granbond_bond_model_new(&p, &bond), "granbond_bond_model_new");
    granbond_voigt_params_default(&vp);
    vp.k_n = 1e4;
    EXPECT_OK(granbond_voigt_model_new(&vp, &voigt), "granbond_voigt_model_new");
    /* type 1: spheres of 1 mm; type 2: none */
    for (t = 0; t < 3; t++) {
        bodies[t].radius_min = INFINITY;
        bodies[t].radius_max = 0.0;
        bodies[t].mass_min = INFINITY;
    }
    bodies[1].radius_min = bodies[1].radius_max = 1e-3;
    bodies[1].mass_min = mass;
    bonds[1 * 3 + 1] = bond;
    bonds[1 * 3 + 2] = bond;
    voigts[1 * 3 + 1] = voigt;

    EXPECT_OK(granbond_bond_critical_timestep(bond, 1e-3, 1e-3, mass, mass, &critical), "granbond_bond_critical_timestep");
    EXPECT_OK(granbond_bond_timestep_check(bonds, 2, bodies, 1.01 * critical, "s", &report), "granbond_bond_timestep_check");
    CHECK(report.level == 2 && report.type_a == 1 && report.type_b == 1 && report.critical == critical,
          say("above the critical step: level 2 on types 1 1 (got %d on %d %d)", report.level, report.type_a, report.type_b));
    CHECK(strstr(report.message, "s: time step") == report.message && strstr(report.message, "EXCEEDS"),
          say("the warning names the style and says EXCEEDS: %s", report.message));
    EXPECT_OK(granbond_bond_timestep_check(bonds, 2, bodies, 0.5 * critical, "s", &report), "granbond_bond_timestep_check");
    CHECK(report.level == 1, "between the recommended and the critical step: level 1");
    EXPECT_OK(granbond_bond_timestep_check(bonds, 2, bodies, 0.1 * critical, "s", &report), "granbond_bond_timestep_check");
    CHECK(report.level == 0 && report.message[0] == 0, "a safe step: level 0, no message");
    EXPECT(granbond_bond_timestep_check(bonds, 2, bodies, NAN, "s", &report), GB_STATUS_INVALID_ARGUMENT,
           "granbond_bond_timestep_check, dt = NaN");
    EXPECT(granbond_bond_timestep_check(bonds, -1, bodies, 1e-6, "s", &report), GB_STATUS_INVALID_ARGUMENT,
           "granbond_bond_timestep_check, ntypes = -1");
    EXPECT_MESSAGE("ntypes");
    EXPECT_NULL_ARG(granbond_bond_timestep_check(NULL, 2, bodies, 1e-6, "s", &report), "granbond_bond_timestep_check",
                    "models");
    EXPECT_NULL_ARG(granbond_bond_timestep_check(bonds, 2, NULL, 1e-6, "s", &report), "granbond_bond_timestep_check",
                    "bodies");
    EXPECT_NULL_ARG(granbond_bond_timestep_check(bonds, 2, bodies, 1e-6, NULL, &report),
                    "granbond_bond_timestep_check", "style");
    EXPECT_NULL_ARG(granbond_bond_timestep_check(bonds, 2, bodies, 1e-6, "s", NULL), "granbond_bond_timestep_check",
                    "out");

    EXPECT_OK(granbond_voigt_critical_timestep(voigt, 1e-3, 1e-3, mass, mass, &critical),
              "granbond_voigt_critical_timestep");
    EXPECT_OK(granbond_voigt_timestep_check(voigts, 2, bodies, 2.0 * critical, "v", &report),
              "granbond_voigt_timestep_check");
    CHECK(report.level == 2 && strstr(report.message, "stiffest contact"), say("voigt: %s", report.message));
    EXPECT_NULL_ARG(granbond_voigt_timestep_check(voigts, 2, bodies, 1e-6, "v", NULL), "granbond_voigt_timestep_check",
                    "out");

    EXPECT_OK(granbond_bond_creation_check(bonds, 2, bodies, 0, 0, 1, "c", &report), "granbond_bond_creation_check");
    CHECK(report.level == 1 && strstr(report.message, "createDistanceBondnonlinear 2.2e-3 m > maxDistanceBondnonlinear"),
          say("createDistance > maxDistance found, LIGGGHTS names: %s", report.message));
    EXPECT_OK(granbond_bond_creation_check(bonds, 2, bodies, 0, 0, 0, "c", &report), "granbond_bond_creation_check");
    CHECK(strstr(report.message, "create_distance 2.2e-3 m > max_distance"), say("LAMMPS names: %s", report.message));
    EXPECT(granbond_bond_creation_check(bonds, 2, bodies, 0, 0, 2, "c", &report), GB_STATUS_INVALID_ARGUMENT,
           "granbond_bond_creation_check, naming = 2");
    EXPECT_NULL_ARG(granbond_bond_creation_check(bonds, 2, bodies, 0, 0, 0, "c", NULL), "granbond_bond_creation_check",
                    "out");

    granbond_bond_model_free(bond);
    granbond_voigt_model_free(voigt);
    return 0;
}

/* ------------------------------------------------------------------------ */
/* Voigt contact                                                             */
/* ------------------------------------------------------------------------ */


static int expect_voigt_refused(const GbVoigtParams *p, size_t id, const char *what)
{
    GbVoigtModel *m = (GbVoigtModel *)(void *)sentinel_object;
    char both[256];
    EXPECT(granbond_voigt_model_new(p, &m), GB_STATUS_INVALID_PARAMETER, what);
    CHECK(granbond_last_error_parameter() == (int32_t)id,
          say("granbond_last_error_parameter() = %d = id of %s", (int)id, VOIGT_FIELDS[id].keyword));
    CHECK(m == NULL, "granbond_voigt_model_new sets *model = NULL on failure");
    snprintf(both, sizeof both, "%s (%s)", VOIGT_FIELDS[id].keyword, VOIGT_FIELDS[id].liggghts);
    EXPECT_MESSAGE(both);
    return 0;
}

static int test_voigt_params(void)
{
    GbVoigtParams p, base;
    GbVoigtModel *m = NULL;
    size_t i;

    memset(&p, 0xAB, sizeof p);
    EXPECT_OK(granbond_voigt_params_default(&p), "granbond_voigt_params_default");
    CHECK(p.k_n == 1.0e4 && p.gamma_n == 1.0e-3 && p.k_t == 6.0e3 && p.gamma_t == 1.0e-3 && p.mu == 0.5 &&
              p.k_r == 1.0e-6 && p.gamma_r == 1.0e-8 && p.mu_r == 5.0e-2 && p.eta_r == 2.0e-8,
          "defaults = Table 1 of the Voigt spec");
    CHECK(p.no_attraction == 1 && p.rolling == 1, "default no_attraction and rolling on");
    base = p;
    EXPECT_OK(granbond_voigt_model_new(&base, &m), "granbond_voigt_model_new(defaults)");
    CHECK(m != NULL, "model created");
    granbond_voigt_model_free(m);
    m = NULL;
    p = base;
    p.k_t = 0.0;
    p.mu = 0.0;
    EXPECT_OK(granbond_voigt_model_new(&p, &m), "granbond_voigt_model_new, k_t = 0, mu = 0");
    granbond_voigt_model_free(m);
    m = NULL;

    p = base;
    p.k_n = 0.0;
    if (expect_voigt_refused(&p, 0, "voigt k_n = 0"))
        return 1;
    p = base;
    p.mu = -1.0;
    if (expect_voigt_refused(&p, 4, "voigt mu = -1"))
        return 1;
    EXPECT_MESSAGE("got -1");
    p = base;
    p.rolling = 2;
    if (expect_voigt_refused(&p, 10, "voigt rolling = 2"))
        return 1;
    for (i = 0; i < N_VOIGT_FIELDS; i++) {
        const struct field *f = &VOIGT_FIELDS[i];
        p = base;
        if (f->type == F_DOUBLE) {
            *double_field(&p, f->offset) = NAN;
            if (expect_voigt_refused(&p, i, say("voigt %s = NaN", f->keyword)))
                return 1;
            p = base;
            *double_field(&p, f->offset) = -2.0;
            if (expect_voigt_refused(&p, i, say("voigt %s = -2", f->keyword)))
                return 1;
        } else {
            *int32_field(&p, f->offset) = -1;
            if (expect_voigt_refused(&p, i, say("voigt %s = -1", f->keyword)))
                return 1;
        }
    }

    CHECK(granbond_voigt_parameter_count() == N_VOIGT_FIELDS, "granbond_voigt_parameter_count = fields");
    for (i = 0; i < N_VOIGT_FIELDS; i++) {
        const char *kw = NULL, *lg = NULL;
        EXPECT_OK(granbond_voigt_parameter_name(i, &kw, &lg), say("granbond_voigt_parameter_name(%u)", (unsigned)i));
        CHECK(strcmp(kw, VOIGT_FIELDS[i].keyword) == 0 && strcmp(lg, VOIGT_FIELDS[i].liggghts) == 0,
              say("voigt parameter %u is %s (%s)", (unsigned)i, VOIGT_FIELDS[i].keyword, VOIGT_FIELDS[i].liggghts));
    }
    {
        const char *kw = NULL, *lg = NULL;
        EXPECT(granbond_voigt_parameter_name(N_VOIGT_FIELDS, &kw, &lg), GB_STATUS_INVALID_ARGUMENT,
               "granbond_voigt_parameter_name(count)");
        EXPECT_NULL_ARG(granbond_voigt_parameter_name(0, NULL, &lg), "granbond_voigt_parameter_name", "keyword");
        EXPECT_NULL_ARG(granbond_voigt_parameter_name(0, &kw, NULL), "granbond_voigt_parameter_name",
                        "liggghts_name");
    }

    EXPECT_NULL_ARG(granbond_voigt_params_default(NULL), "granbond_voigt_params_default", "params");
    m = (GbVoigtModel *)(void *)sentinel_object;
    EXPECT_NULL_ARG(granbond_voigt_model_new(NULL, &m), "granbond_voigt_model_new", "params");
    CHECK(m == NULL, "granbond_voigt_model_new(NULL params) sets *model = NULL");
    EXPECT_NULL_ARG(granbond_voigt_model_new(&base, NULL), "granbond_voigt_model_new", "model");
    return 0;
}

#define R_C 1.0e-3

static int new_voigt_model(const GbVoigtParams *p, GbVoigtModel **m)
{
    *m = NULL;
    EXPECT_OK(granbond_voigt_model_new(p, m), "granbond_voigt_model_new");
    CHECK(*m != NULL, "model is not NULL");
    return 0;
}

/* Two spheres of radius R_C overlapping by `overlap`, i approaching j at
 * `speed` along the centre line. */
static void contact_at(GbPairKinematics *k, double overlap, double speed)
{
    int c;
    pair_at(k, 2.0 * R_C - overlap, R_C, R_C);
    for (c = 0; c < 3; c++)
        k->v_i[c] = -speed * AXIS[c];
}

static int test_voigt_contact(void)
{
    const GbVoigtParams p = voigt_fixture();
    GbVoigtModel *m = NULL;
    GbPairKinematics k, bad;
    GbContactOutput out;
    double state[GRANBOND_CONTACT_STATE_LEN], copy[GRANBOND_CONTACT_STATE_LEN];
    double n[3], expected[3], v_rel[3], r, overlap, v_n, fn;
    int c;

    if (new_voigt_model(&p, &m))
        return 1;
    memset(state, 0, sizeof state);

    /* Overlap, approaching: Fn = k_n overlap - gamma_n v_n along n. */
    contact_at(&k, 1.0e-5, 0.01);
    EXPECT_OK(granbond_voigt_compute(m, &k, DT, state, &out), "granbond_voigt_compute, overlapping");
    r = distance3(k.x_i, k.x_j);
    for (c = 0; c < 3; c++) {
        n[c] = (k.x_i[c] - k.x_j[c]) / r;
        v_rel[c] = k.v_i[c] - k.v_j[c];
    }
    overlap = k.radius_i + k.radius_j - r;
    v_n = dot3(v_rel, n);
    fn = p.k_n * overlap - p.gamma_n * v_n;
    for (c = 0; c < 3; c++)
        expected[c] = fn * n[c];
    CHECK(v_n < 0.0, "approaching: v_n < 0");
    CHECK(close_to(out.overlap, overlap, 1e-12), say("out.overlap = %.17g", overlap));
    CHECK(close_to(out.normal_force, fn, 1e-12), say("out.normal_force = k_n overlap - gamma_n v_n = %.17g N", fn));
    CHECK(vec_close(out.force_i, expected, 1e-12), "force on i = Fn n to 1e-12");
    CHECK(dot3(out.force_i, n) > 0.0, "repulsive");
    CHECK(out.touching == 1 && out.sliding == 0 && out.rolling_slip == 0, "touching, not sliding");

    /* Separating fast: no attraction clamps Fn at 0. */
    contact_at(&k, 1.0e-6, -100.0);
    EXPECT_OK(granbond_voigt_compute(m, &k, DT, state, &out), "granbond_voigt_compute, separating fast");
    CHECK(out.normal_force == 0.0 && out.touching == 1, "no attraction: Fn = 0");

    /* Apart: nothing, and the history is forgotten. */
    for (c = 0; c < GRANBOND_CONTACT_STATE_LEN; c++)
        state[c] = 1.0e-9 * (c + 1);
    contact_at(&k, -1.0e-5, 0.0);
    EXPECT_OK(granbond_voigt_compute(m, &k, DT, state, &out), "granbond_voigt_compute, apart");
    CHECK(out.touching == 0 && vec_zero(out.force_i) && vec_zero(out.torque_i) && vec_zero(out.torque_j) &&
              out.normal_force == 0.0,
          "apart: not touching, no force, no torque");
    CHECK(close_to(out.overlap, -1.0e-5, 1e-9), "apart: overlap < 0 reported");
    for (c = 0; c < GRANBOND_CONTACT_STATE_LEN; c++)
        CHECK(state[c] == 0.0, say("apart: state slot %d zeroed", c));

    /* Errors. */
    contact_at(&k, 1.0e-5, 0.01);
    memcpy(copy, state, sizeof state);
    bad = k;
    memcpy(bad.x_i, bad.x_j, sizeof bad.x_i);
    EXPECT(granbond_voigt_compute(m, &bad, DT, state, &out), GB_STATUS_COINCIDENT_CENTRES,
           "granbond_voigt_compute, coincident centres");
    bad = k;
    bad.w_i[2] = NAN;
    EXPECT(granbond_voigt_compute(m, &bad, DT, state, &out), GB_STATUS_NON_FINITE_INPUT,
           "granbond_voigt_compute, NaN w_i");
    bad = k;
    bad.radius_j = 0.0;
    EXPECT(granbond_voigt_compute(m, &bad, DT, state, &out), GB_STATUS_NON_POSITIVE_RADIUS,
           "granbond_voigt_compute, radius_j = 0");
    EXPECT(granbond_voigt_compute(m, &k, -DT, state, &out), GB_STATUS_INVALID_ARGUMENT,
           "granbond_voigt_compute, dt < 0");
    EXPECT(granbond_voigt_compute(m, &k, NAN, state, &out), GB_STATUS_INVALID_ARGUMENT,
           "granbond_voigt_compute, dt = NaN");
    CHECK(memcmp(copy, state, sizeof state) == 0, "state untouched");

    EXPECT_NULL_ARG(granbond_voigt_compute(NULL, &k, DT, state, &out), "granbond_voigt_compute", "model");
    EXPECT_NULL_ARG(granbond_voigt_compute(m, NULL, DT, state, &out), "granbond_voigt_compute", "kinematics");
    EXPECT_NULL_ARG(granbond_voigt_compute(m, &k, DT, NULL, &out), "granbond_voigt_compute", "state");
    EXPECT_NULL_ARG(granbond_voigt_compute(m, &k, DT, state, NULL), "granbond_voigt_compute", "out");

    granbond_voigt_model_free(m);
    return 0;
}

#define N_CONTACTS 3

static int test_voigt_batch(void)
{
    const GbVoigtParams p = voigt_fixture();
    GbVoigtModel *m = NULL;
    GbPairKinematics k[N_CONTACTS];
    GbContactOutput out[N_CONTACTS], single;
    double states[N_CONTACTS * GRANBOND_CONTACT_STATE_LEN], one[GRANBOND_CONTACT_STATE_LEN];
    size_t failed = 999;
    int b;

    if (new_voigt_model(&p, &m))
        return 1;
    for (b = 0; b < N_CONTACTS; b++) {
        contact_at(&k[b], 1.0e-6 * (b + 1), 0.01 * b);
        k[b].v_i[0] += 1.0e-3; /* some sliding velocity too */
        k[b].w_i[1] = 0.3;
    }
    memset(states, 0, sizeof states);

    k[1].radius_i = 0.0;
    memset(out, 0, sizeof out);
    out[2].touching = -7;
    EXPECT(granbond_voigt_compute_batch(m, N_CONTACTS, k, DT, states, out, &failed), GB_STATUS_NON_POSITIVE_RADIUS,
           "granbond_voigt_compute_batch with radius 0 in contact 1");
    CHECK(failed == 1, say("failed_index = 1 (got %u)", (unsigned)failed));
    EXPECT_MESSAGE("contact 1");
    CHECK(out[0].touching == 1 && out[2].touching == -7, "contact 0 computed, contact 2 not touched");
    EXPECT(granbond_voigt_compute_batch(m, N_CONTACTS, k, DT, states, out, NULL), GB_STATUS_NON_POSITIVE_RADIUS,
           "the same batch with failed_index = NULL");
    k[1].radius_i = R_C;

    memset(states, 0, sizeof states);
    failed = 999;
    EXPECT_OK(granbond_voigt_compute_batch(m, N_CONTACTS, k, DT, states, out, &failed),
              "granbond_voigt_compute_batch");
    CHECK(failed == 999, "failed_index left alone on success");
    for (b = 0; b < N_CONTACTS; b++) {
        memset(one, 0, sizeof one);
        EXPECT_OK(granbond_voigt_compute(m, &k[b], DT, one, &single), say("granbond_voigt_compute, contact %d", b));
        CHECK(vec_close(out[b].force_i, single.force_i, 1e-15) && vec_close(out[b].torque_i, single.torque_i, 1e-15) &&
                  memcmp(one, states + b * GRANBOND_CONTACT_STATE_LEN, sizeof one) == 0 && out[b].touching == 1,
              say("batch contact %d = single call", b));
    }

    EXPECT(granbond_voigt_compute_batch(m, N_CONTACTS, k, INFINITY, states, out, &failed),
           GB_STATUS_INVALID_ARGUMENT, "granbond_voigt_compute_batch with dt = inf");
    EXPECT_OK(granbond_voigt_compute_batch(m, 0, NULL, DT, NULL, NULL, NULL),
              "granbond_voigt_compute_batch, count = 0 and NULL arrays");
    EXPECT_NULL_ARG(granbond_voigt_compute_batch(NULL, N_CONTACTS, k, DT, states, out, &failed),
                    "granbond_voigt_compute_batch", "model");
    EXPECT_NULL_ARG(granbond_voigt_compute_batch(m, N_CONTACTS, NULL, DT, states, out, &failed),
                    "granbond_voigt_compute_batch", "kinematics");
    EXPECT_NULL_ARG(granbond_voigt_compute_batch(m, N_CONTACTS, k, DT, NULL, out, &failed),
                    "granbond_voigt_compute_batch", "states");
    EXPECT_NULL_ARG(granbond_voigt_compute_batch(m, N_CONTACTS, k, DT, states, NULL, &failed),
                    "granbond_voigt_compute_batch", "out");

    granbond_voigt_model_free(m);
    return 0;
}

static int test_voigt_plane(void)
{
    const GbVoigtParams p = voigt_fixture();
    GbVoigtModel *m = NULL;
    GbSphereKinematics sphere, bad;
    GbPlane plane, tilted;
    GbContactOutput out;
    double state[GRANBOND_CONTACT_STATE_LEN];
    const double overlap = 2.0e-5, speed = 0.02;
    double fn;

    if (new_voigt_model(&p, &m))
        return 1;
    memset(state, 0, sizeof state);
    memset(&plane, 0, sizeof plane);
    plane.point[0] = 0.3;
    plane.point[1] = -0.1;
    plane.normal[2] = 1.0;
    memset(&sphere, 0, sizeof sphere);
    sphere.radius = R_C;
    sphere.x[0] = 0.3;
    sphere.x[1] = -0.1;
    sphere.x[2] = R_C - overlap;
    sphere.v[2] = -speed;

    EXPECT_OK(granbond_voigt_compute_plane(m, &sphere, &plane, DT, state, &out),
              "granbond_voigt_compute_plane, sphere pressed into the plane");
    fn = p.k_n * (R_C - sphere.x[2]) + p.gamma_n * speed;
    CHECK(close_to(out.overlap, R_C - sphere.x[2], 1e-12), "plane overlap = R - gap");
    CHECK(close_to(out.normal_force, fn, 1e-12), say("plane Fn = k_n overlap - gamma_n v_n = %.17g N", fn));
    CHECK(close_to(out.force_i[2], fn, 1e-12) && out.force_i[0] == 0.0 && out.force_i[1] == 0.0,
          "force along the plane normal, repulsive");
    CHECK(out.touching == 1, "touching");

    /* The plane's normal must be a unit vector; any unit direction will do. */
    tilted = plane;
    tilted.normal[2] = 2.0;
    EXPECT(granbond_voigt_compute_plane(m, &sphere, &tilted, DT, state, &out), GB_STATUS_INVALID_ARGUMENT,
           "granbond_voigt_compute_plane, |normal| = 2");
    EXPECT_MESSAGE("unit");
    tilted.normal[2] = 0.0;
    EXPECT(granbond_voigt_compute_plane(m, &sphere, &tilted, DT, state, &out), GB_STATUS_INVALID_ARGUMENT,
           "granbond_voigt_compute_plane, normal = 0");
    tilted.normal[0] = 0.0;
    tilted.normal[1] = 0.6;
    tilted.normal[2] = 0.8;
    EXPECT_OK(granbond_voigt_compute_plane(m, &sphere, &tilted, DT, state, &out),
              "granbond_voigt_compute_plane, normal (0, 0.6, 0.8)");

    tilted = plane;
    tilted.point[0] = NAN;
    EXPECT(granbond_voigt_compute_plane(m, &sphere, &tilted, DT, state, &out), GB_STATUS_NON_FINITE_INPUT,
           "granbond_voigt_compute_plane, NaN plane point");
    tilted = plane;
    tilted.velocity[1] = INFINITY;
    EXPECT(granbond_voigt_compute_plane(m, &sphere, &tilted, DT, state, &out), GB_STATUS_NON_FINITE_INPUT,
           "granbond_voigt_compute_plane, inf plane velocity");
    bad = sphere;
    bad.radius = 0.0;
    EXPECT(granbond_voigt_compute_plane(m, &bad, &plane, DT, state, &out), GB_STATUS_NON_POSITIVE_RADIUS,
           "granbond_voigt_compute_plane, radius 0");
    EXPECT(granbond_voigt_compute_plane(m, &sphere, &plane, -DT, state, &out), GB_STATUS_INVALID_ARGUMENT,
           "granbond_voigt_compute_plane, dt < 0");

    EXPECT_NULL_ARG(granbond_voigt_compute_plane(NULL, &sphere, &plane, DT, state, &out),
                    "granbond_voigt_compute_plane", "model");
    EXPECT_NULL_ARG(granbond_voigt_compute_plane(m, NULL, &plane, DT, state, &out), "granbond_voigt_compute_plane",
                    "sphere");
    EXPECT_NULL_ARG(granbond_voigt_compute_plane(m, &sphere, NULL, DT, state, &out), "granbond_voigt_compute_plane",
                    "plane");
    EXPECT_NULL_ARG(granbond_voigt_compute_plane(m, &sphere, &plane, DT, NULL, &out),
                    "granbond_voigt_compute_plane", "state");
    EXPECT_NULL_ARG(granbond_voigt_compute_plane(m, &sphere, &plane, DT, state, NULL),
                    "granbond_voigt_compute_plane", "out");

    granbond_voigt_model_free(m);
    return 0;
}

static int test_voigt_timestep(void)
{
    const GbVoigtParams p = voigt_fixture();
    GbVoigtModel *m = NULL;
    const double mass = 2500.0 * 4.0 / 3.0 * PI * R_C * R_C * R_C;
    double dt = -1.0, bound;

    if (new_voigt_model(&p, &m))
        return 1;
    EXPECT_OK(granbond_voigt_critical_timestep(m, R_C, R_C, mass, mass, &dt), "granbond_voigt_critical_timestep");
    bound = 2.0 * sqrt(0.5 * mass / p.k_n);
    CHECK(isfinite(dt) && dt > 0.0, say("critical time step %.6g s is positive and finite", dt));
    CHECK(dt <= bound * (1.0 + 1e-12), say("critical time step <= 2 sqrt(m_eff / k_n) = %.6g s", bound));
    EXPECT(granbond_voigt_critical_timestep(m, R_C, R_C, 0.0, mass, &dt), GB_STATUS_INVALID_ARGUMENT,
           "granbond_voigt_critical_timestep, mass_i = 0");
    EXPECT_MESSAGE("mass_i");
    EXPECT(granbond_voigt_critical_timestep(m, R_C, R_C, mass, NAN, &dt), GB_STATUS_INVALID_ARGUMENT,
           "granbond_voigt_critical_timestep, mass_j = NaN");
    EXPECT(granbond_voigt_critical_timestep(m, R_C, -R_C, mass, mass, &dt), GB_STATUS_INVALID_ARGUMENT,
           "granbond_voigt_critical_timestep, radius_j < 0");
    EXPECT_MESSAGE("radius_j");
    EXPECT_NULL_ARG(granbond_voigt_critical_timestep(NULL, R_C, R_C, mass, mass, &dt),
                    "granbond_voigt_critical_timestep", "model");
    EXPECT_NULL_ARG(granbond_voigt_critical_timestep(m, R_C, R_C, mass, mass, NULL),
                    "granbond_voigt_critical_timestep", "out");
    granbond_voigt_model_free(m);
    return 0;
}

/* ------------------------------------------------------------------------ */
/* Voigt contact in separate parts over a contact frame                      */
/* ------------------------------------------------------------------------ */

static int vec_equal(const double a[3], const double b[3])
{
    return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

static int test_contact_frames(void)
{
    GbPairKinematics k, bad;
    GbSphereKinematics sphere, bad_sphere;
    GbPlane plane, tilted;
    GbContactFrame frame;
    double n[3], r;
    int c;

    /* Sphere pair. */
    contact_at(&k, 1.0e-5, 0.01);
    k.radius_j = 0.7e-3;
    k.w_i[0] = 0.2;
    k.w_j[1] = -0.3;
    k.v_j[2] = 0.004;
    memset(&frame, 0xAB, sizeof frame);
    EXPECT_OK(granbond_contact_frame_pair(&k, &frame), "granbond_contact_frame_pair");
    r = distance3(k.x_i, k.x_j);
    for (c = 0; c < 3; c++)
        n[c] = (k.x_i[c] - k.x_j[c]) / r;
    CHECK(vec_close(frame.n, n, 1e-15), "frame.n = (x_i - x_j) / |x_i - x_j|");
    CHECK(close_to(frame.overlap, k.radius_i + k.radius_j - r, 1e-12), "frame.overlap = R_i + R_j - r");
    CHECK(frame.lever_i == k.radius_i && frame.lever_j == k.radius_j, "frame levers = radii");
    CHECK(close_to(frame.r_eff, k.radius_i * k.radius_j / (k.radius_i + k.radius_j), 1e-15),
          "frame.r_eff = R_i R_j / (R_i + R_j)");
    CHECK(vec_equal(frame.v_i, k.v_i) && vec_equal(frame.v_j, k.v_j) && vec_equal(frame.w_i, k.w_i) &&
              vec_equal(frame.w_j, k.w_j),
          "frame velocities = kinematics");
    bad = k;
    memcpy(bad.x_j, bad.x_i, sizeof bad.x_j);
    EXPECT(granbond_contact_frame_pair(&bad, &frame), GB_STATUS_COINCIDENT_CENTRES,
           "granbond_contact_frame_pair, coincident centres");
    bad = k;
    bad.v_j[0] = NAN;
    EXPECT(granbond_contact_frame_pair(&bad, &frame), GB_STATUS_NON_FINITE_INPUT,
           "granbond_contact_frame_pair, NaN v_j");
    bad = k;
    bad.radius_i = 0.0;
    EXPECT(granbond_contact_frame_pair(&bad, &frame), GB_STATUS_NON_POSITIVE_RADIUS,
           "granbond_contact_frame_pair, radius 0");
    EXPECT_NULL_ARG(granbond_contact_frame_pair(NULL, &frame), "granbond_contact_frame_pair", "kinematics");
    EXPECT_NULL_ARG(granbond_contact_frame_pair(&k, NULL), "granbond_contact_frame_pair", "frame");

    /* Sphere on a plane: the wall is the j side, with no lever and no spin. */
    memset(&plane, 0, sizeof plane);
    plane.point[2] = 0.5e-3;
    plane.normal[2] = 1.0;
    plane.velocity[0] = 0.01;
    memset(&sphere, 0, sizeof sphere);
    sphere.radius = R_C;
    sphere.x[2] = 0.5e-3 + R_C - 3.0e-5;
    sphere.v[2] = -0.02;
    sphere.w[1] = 1.5;
    memset(&frame, 0xAB, sizeof frame);
    EXPECT_OK(granbond_contact_frame_plane(&sphere, &plane, &frame), "granbond_contact_frame_plane");
    CHECK(vec_equal(frame.n, plane.normal), "frame.n = plane normal");
    CHECK(close_to(frame.overlap, 3.0e-5, 1e-9), "frame.overlap = R - gap");
    CHECK(frame.lever_i == R_C && frame.lever_j == 0.0 && frame.r_eff == R_C, "levers R and 0, r_eff = R");
    CHECK(vec_equal(frame.v_i, sphere.v) && vec_equal(frame.v_j, plane.velocity) && vec_equal(frame.w_i, sphere.w) &&
              vec_zero(frame.w_j),
          "frame velocities: sphere, wall, no wall spin");
    tilted = plane;
    tilted.normal[2] = 0.5;
    EXPECT(granbond_contact_frame_plane(&sphere, &tilted, &frame), GB_STATUS_INVALID_ARGUMENT,
           "granbond_contact_frame_plane, |normal| = 0.5");
    EXPECT_MESSAGE("unit");
    bad_sphere = sphere;
    bad_sphere.w[2] = INFINITY;
    EXPECT(granbond_contact_frame_plane(&bad_sphere, &plane, &frame), GB_STATUS_NON_FINITE_INPUT,
           "granbond_contact_frame_plane, inf spin");
    bad_sphere = sphere;
    bad_sphere.radius = 0.0;
    EXPECT(granbond_contact_frame_plane(&bad_sphere, &plane, &frame), GB_STATUS_NON_POSITIVE_RADIUS,
           "granbond_contact_frame_plane, radius 0");
    EXPECT_NULL_ARG(granbond_contact_frame_plane(NULL, &plane, &frame), "granbond_contact_frame_plane", "sphere");
    EXPECT_NULL_ARG(granbond_contact_frame_plane(&sphere, NULL, &frame), "granbond_contact_frame_plane", "plane");
    EXPECT_NULL_ARG(granbond_contact_frame_plane(&sphere, &plane, NULL), "granbond_contact_frame_plane", "frame");
    return 0;
}

/* normal + tangential + rolling over a frame, assembled as an engine would. */
static int voigt_by_parts(const GbVoigtModel *m, const GbContactFrame *f, int rolling, double dt, double *state,
                          GbContactOutput *out)
{
    GbTangentialOutput t;
    double fn = -1.0, t_r[3] = {0.0, 0.0, 0.0};
    int32_t slip = 0;
    int c;
    EXPECT_OK(granbond_voigt_normal_force(m, f, &fn), "granbond_voigt_normal_force");
    EXPECT_OK(granbond_voigt_tangential(m, f, fn, dt, state, &t), "granbond_voigt_tangential");
    if (rolling)
        EXPECT_OK(granbond_voigt_rolling(m, f, fn, dt, state + 3, t_r, &slip), "granbond_voigt_rolling");
    memset(out, 0, sizeof *out);
    for (c = 0; c < 3; c++) {
        out->force_i[c] = f->n[c] * fn + t.force_i[c];
        out->torque_i[c] = t.torque_i[c] + t_r[c];
        out->torque_j[c] = t.torque_j[c] - t_r[c];
    }
    out->normal_force = fn;
    out->overlap = f->overlap;
    out->touching = 1;
    out->sliding = t.sliding;
    out->rolling_slip = slip;
    return 0;
}

static int same_contact_output(const GbContactOutput *a, const GbContactOutput *b)
{
    return vec_close(a->force_i, b->force_i, 1e-15) && vec_close(a->torque_i, b->torque_i, 1e-15) &&
           vec_close(a->torque_j, b->torque_j, 1e-15) && close_to(a->normal_force, b->normal_force, 1e-15) &&
           a->touching == b->touching && a->sliding == b->sliding && a->rolling_slip == b->rolling_slip;
}

static int identical_contact_output(const GbContactOutput *a, const GbContactOutput *b)
{
    return memcmp(a->force_i, b->force_i, sizeof a->force_i) == 0 &&
           memcmp(a->torque_i, b->torque_i, sizeof a->torque_i) == 0 &&
           memcmp(a->torque_j, b->torque_j, sizeof a->torque_j) == 0 &&
           memcmp(&a->normal_force, &b->normal_force, sizeof a->normal_force) == 0 &&
           memcmp(&a->overlap, &b->overlap, sizeof a->overlap) == 0 && a->touching == b->touching &&
           a->sliding == b->sliding && a->rolling_slip == b->rolling_slip;
}

static int test_voigt_parts(void)
{
    const GbVoigtParams p = voigt_fixture();
    GbVoigtModel *m = NULL;
    GbPairKinematics k;
    GbContactFrame frame, bad;
    GbContactOutput whole, parts;
    GbTangentialOutput t;
    double state_whole[GRANBOND_CONTACT_STATE_LEN], state_parts[GRANBOND_CONTACT_STATE_LEN];
    double state_fields[GRANBOND_CONTACT_STATE_LEN];
    double state_sep[GRANBOND_CONTACT_STATE_LEN], state_normal[GRANBOND_CONTACT_STATE_LEN];
    GbContactOutput fields, sep, normal;
    GbContactFrame built;
    double del[3], rsq, distance;
    double fn = 0.0, v_rel[3], torque[3], spring[3] = {0.0, 0.0, 0.0}, angle[3] = {0.0, 0.0, 0.0};
    int32_t slip = 0;
    int step, c;

    if (new_voigt_model(&p, &m))
        return 1;

    /* The parts, and the unchecked whole step on the frame, reproduce
     * granbond_voigt_compute, step after step. */
    memset(state_whole, 0, sizeof state_whole);
    memset(state_parts, 0, sizeof state_parts);
    memset(state_fields, 0, sizeof state_fields);
    memset(state_sep, 0, sizeof state_sep);
    memset(state_normal, 0, sizeof state_normal);
    for (step = 0; step < 4; step++) {
        contact_at(&k, 1.0e-5 + 1.0e-6 * step, 0.01);
        k.v_i[0] += 2.0e-3;
        k.w_i[1] = 0.4;
        k.w_j[0] = -0.1 * step;
        EXPECT_OK(granbond_voigt_compute(m, &k, DT, state_whole, &whole), say("granbond_voigt_compute, step %d", step));
        EXPECT_OK(granbond_contact_frame_pair(&k, &frame), say("granbond_contact_frame_pair, step %d", step));
        if (voigt_by_parts(m, &frame, p.rolling, DT, state_parts, &parts))
            return 1;
        CHECK(same_contact_output(&whole, &parts), say("step %d: normal + tangential + rolling = whole step", step));
        CHECK(vec_close(state_whole, state_parts, 1e-15) && vec_close(state_whole + 3, state_parts + 3, 1e-15),
              say("step %d: same spring and rolling angle", step));
        EXPECT_OK(granbond_voigt_compute_fields_unchecked(m, frame.n, frame.overlap, frame.lever_i, frame.lever_j,
                                                          frame.r_eff, frame.v_i, frame.v_j, frame.w_i, frame.w_j, DT,
                                                          state_fields, &fields),
                  say("granbond_voigt_compute_fields_unchecked, step %d", step));
        CHECK(same_contact_output(&fields, &whole) && memcmp(state_fields, state_whole, sizeof state_fields) == 0,
              say("step %d: unchecked step on the frame's fields = granbond_voigt_compute", step));
        /* From the engine's geometry and the radii: the same frame, the same bits. */
        for (c = 0; c < 3; c++)
            del[c] = k.x_i[c] - k.x_j[c];
        rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
        distance = sqrt(rsq);
        EXPECT_OK(granbond_contact_frame_separation(del, rsq, k.radius_i, k.radius_j, k.v_i, k.v_j, k.w_i, k.w_j,
                                                    &built),
                  say("granbond_contact_frame_separation, step %d", step));
        CHECK(memcmp(&built, &frame, sizeof built) == 0,
              say("step %d: the frame from the separation = granbond_contact_frame_pair, bit for bit", step));
        EXPECT_OK(granbond_contact_frame_normal(frame.n, distance, k.radius_i, k.radius_j, k.v_i, k.v_j, k.w_i, k.w_j,
                                                &built),
                  say("granbond_contact_frame_normal, step %d", step));
        CHECK(memcmp(&built, &frame, sizeof built) == 0,
              say("step %d: the frame from the normal and distance = granbond_contact_frame_pair", step));
        EXPECT_OK(granbond_voigt_compute_separation_unchecked(m, del, rsq, k.radius_i, k.radius_j, k.v_i, k.v_j, k.w_i,
                                                              k.w_j, DT, state_sep, &sep),
                  say("granbond_voigt_compute_separation_unchecked, step %d", step));
        CHECK(identical_contact_output(&sep, &fields) && memcmp(state_sep, state_fields, sizeof state_fields) == 0,
              say("step %d: unchecked step on the separation = on the frame's fields, bit for bit", step));
        EXPECT_OK(granbond_voigt_compute_normal_unchecked(m, frame.n, distance, k.radius_i, k.radius_j, k.v_i, k.v_j,
                                                          k.w_i, k.w_j, DT, state_normal, &normal),
                  say("granbond_voigt_compute_normal_unchecked, step %d", step));
        CHECK(identical_contact_output(&normal, &fields) && memcmp(state_normal, state_fields, sizeof state_fields) == 0,
              say("step %d: unchecked step on the normal and distance = on the frame's fields, bit for bit", step));
    }
    EXPECT_NULL_ARG(granbond_contact_frame_separation(NULL, rsq, k.radius_i, k.radius_j, k.v_i, k.v_j, k.w_i, k.w_j,
                                                      &built),
                    "granbond_contact_frame_separation", "del");
    EXPECT_NULL_ARG(granbond_contact_frame_normal(frame.n, distance, k.radius_i, k.radius_j, k.v_i, k.v_j, k.w_i, k.w_j,
                                                  NULL),
                    "granbond_contact_frame_normal", "frame");
    bad = frame;
    bad.w_j[2] = NAN;
    EXPECT(granbond_voigt_compute_fields_unchecked(m, bad.n, bad.overlap, bad.lever_i, bad.lever_j, bad.r_eff, bad.v_i,
                                                   bad.v_j, bad.w_i, bad.w_j, DT, state_fields, &fields),
           GB_STATUS_NON_FINITE_INPUT, "granbond_voigt_compute_fields_unchecked, NaN w_j: a non-finite torque is reported");
    EXPECT_MESSAGE("granbond_voigt_compute_fields_unchecked");

    /* The normal part alone: k_n overlap - gamma_n v_n. */
    contact_at(&k, 1.0e-5, 0.01);
    EXPECT_OK(granbond_contact_frame_pair(&k, &frame), "granbond_contact_frame_pair");
    EXPECT_OK(granbond_voigt_normal_force(m, &frame, &fn), "granbond_voigt_normal_force");
    for (c = 0; c < 3; c++)
        v_rel[c] = frame.v_i[c] - frame.v_j[c];
    CHECK(close_to(fn, p.k_n * frame.overlap - p.gamma_n * dot3(v_rel, frame.n), 1e-12),
          "granbond_voigt_normal_force = k_n overlap - gamma_n v_n");

    /* Sliding: the tangential force sits on the Coulomb cap mu |Fn|. */
    k.v_i[0] += 10.0;
    EXPECT_OK(granbond_contact_frame_pair(&k, &frame), "granbond_contact_frame_pair, fast slip");
    EXPECT_OK(granbond_voigt_tangential(m, &frame, fn, 1.0e-3, spring, &t), "granbond_voigt_tangential, fast slip");
    CHECK(t.sliding == 1 && close_to(norm3(t.force_i), p.mu * fabs(fn), 1e-12), "sliding: |Ft| = mu |Fn|");
    CHECK(fabs(dot3(t.force_i, frame.n)) <= 1e-12 * norm3(t.force_i), "Ft is tangential");

    /* A model without rolling resistance gives no rolling torque and
     * forgets the rolling angle. */
    {
        GbVoigtParams q = p;
        GbVoigtModel *off = NULL;
        double a[3] = {1.0e-3, 2.0e-3, 0.0}, tq[3] = {1.0, 1.0, 1.0};
        int32_t sl = 7;
        q.rolling = 0;
        if (new_voigt_model(&q, &off))
            return 1;
        EXPECT_OK(granbond_voigt_rolling(off, &frame, fn, DT, a, tq, &sl), "granbond_voigt_rolling, rolling off");
        CHECK(norm3(tq) == 0.0 && norm3(a) == 0.0 && sl == 0, "rolling off: no torque, angle zeroed");
        granbond_voigt_model_free(off);
    }

    /* Evaluating without advancing: the stored state is read, not written,
     * and a step of the same frame with dt = 0 gives the same loads. */
    {
        double held[GRANBOND_CONTACT_STATE_LEN] = {1.0e-7, -2.0e-7, 0.0, 3.0e-4, 1.0e-4, 0.0};
        double copy[GRANBOND_CONTACT_STATE_LEN], tq[3], tq0[3];
        GbContactOutput ev, st;
        GbTangentialOutput te, t0;
        int32_t sl = 0, sl0 = 0;
        memcpy(copy, held, sizeof held);
        EXPECT_OK(granbond_voigt_evaluate_frame(m, &frame, held, &ev), "granbond_voigt_evaluate_frame");
        CHECK(memcmp(copy, held, sizeof held) == 0, "granbond_voigt_evaluate_frame leaves the state alone");
        EXPECT_OK(granbond_voigt_compute_fields_unchecked(m, frame.n, frame.overlap, frame.lever_i, frame.lever_j,
                                                          frame.r_eff, frame.v_i, frame.v_j, frame.w_i, frame.w_j, 0.0,
                                                          copy, &st),
                  "granbond_voigt_compute_fields_unchecked, dt = 0");
        CHECK(close_to(ev.force_i[0], st.force_i[0], 1e-15) && close_to(ev.force_i[1], st.force_i[1], 1e-15) &&
                  close_to(ev.torque_i[2], st.torque_i[2], 1e-15),
              "evaluation = a step of zero length");
        memcpy(copy, held, sizeof held);
        EXPECT_OK(granbond_voigt_tangential_evaluate(m, &frame, fn, held, &te), "granbond_voigt_tangential_evaluate");
        EXPECT_OK(granbond_voigt_tangential(m, &frame, fn, 0.0, copy, &t0), "granbond_voigt_tangential, dt = 0");
        CHECK(close_to(te.force_i[1], t0.force_i[1], 1e-15), "tangential evaluation = a step of zero length");
        EXPECT_OK(granbond_voigt_rolling_evaluate(m, &frame, fn, held + 3, tq, &sl), "granbond_voigt_rolling_evaluate");
        EXPECT_OK(granbond_voigt_rolling(m, &frame, fn, 0.0, copy + 3, tq0, &sl0), "granbond_voigt_rolling, dt = 0");
        CHECK(close_to(tq[0], tq0[0], 1e-15) && sl == sl0, "rolling evaluation = a step of zero length");
        EXPECT_NULL_ARG(granbond_voigt_evaluate_frame(m, &frame, NULL, &ev), "granbond_voigt_evaluate_frame",
                        "state");
        EXPECT_NULL_ARG(granbond_voigt_tangential_evaluate(m, &frame, fn, NULL, &te),
                        "granbond_voigt_tangential_evaluate", "spring");
        EXPECT_NULL_ARG(granbond_voigt_rolling_evaluate(m, &frame, fn, held, NULL, &sl),
                        "granbond_voigt_rolling_evaluate", "torque_i");
        bad = frame;
        bad.v_i[0] = NAN;
        EXPECT(granbond_voigt_evaluate_frame(m, &bad, held, &ev), GB_STATUS_NON_FINITE_INPUT,
               "granbond_voigt_evaluate_frame, NaN v_i");
    }

    /* Errors. */
    bad = frame;
    bad.overlap = NAN;
    EXPECT(granbond_voigt_normal_force(m, &bad, &fn), GB_STATUS_NON_FINITE_INPUT,
           "granbond_voigt_normal_force, NaN overlap");
    bad = frame;
    bad.n[0] *= 2.0;
    EXPECT(granbond_voigt_normal_force(m, &bad, &fn), GB_STATUS_INVALID_ARGUMENT,
           "granbond_voigt_normal_force, non-unit normal");
    EXPECT_MESSAGE("unit");
    bad = frame;
    bad.w_j[1] = -INFINITY;
    EXPECT(granbond_voigt_tangential(m, &bad, fn, DT, spring, &t), GB_STATUS_NON_FINITE_INPUT,
           "granbond_voigt_tangential, -inf w_j");
    EXPECT(granbond_voigt_tangential(m, &frame, fn, -DT, spring, &t), GB_STATUS_INVALID_ARGUMENT,
           "granbond_voigt_tangential, dt < 0");
    EXPECT(granbond_voigt_tangential(m, &frame, NAN, DT, spring, &t), GB_STATUS_NON_FINITE_INPUT,
           "granbond_voigt_tangential, NaN normal force");
    EXPECT(granbond_voigt_rolling(m, &frame, INFINITY, DT, angle, torque, &slip), GB_STATUS_NON_FINITE_INPUT,
           "granbond_voigt_rolling, infinite normal force");
    EXPECT(granbond_voigt_rolling(m, &bad, fn, DT, angle, torque, &slip), GB_STATUS_NON_FINITE_INPUT,
           "granbond_voigt_rolling, -inf w_j");
    EXPECT(granbond_voigt_rolling(m, &frame, fn, NAN, angle, torque, &slip), GB_STATUS_INVALID_ARGUMENT,
           "granbond_voigt_rolling, dt = NaN");

    EXPECT_NULL_ARG(granbond_voigt_normal_force(NULL, &frame, &fn), "granbond_voigt_normal_force", "model");
    EXPECT_NULL_ARG(granbond_voigt_normal_force(m, NULL, &fn), "granbond_voigt_normal_force", "frame");
    EXPECT_NULL_ARG(granbond_voigt_normal_force(m, &frame, NULL), "granbond_voigt_normal_force", "normal_force");
    EXPECT_NULL_ARG(granbond_voigt_tangential(NULL, &frame, fn, DT, spring, &t), "granbond_voigt_tangential",
                    "model");
    EXPECT_NULL_ARG(granbond_voigt_tangential(m, NULL, fn, DT, spring, &t), "granbond_voigt_tangential", "frame");
    EXPECT_NULL_ARG(granbond_voigt_tangential(m, &frame, fn, DT, NULL, &t), "granbond_voigt_tangential", "spring");
    EXPECT_NULL_ARG(granbond_voigt_tangential(m, &frame, fn, DT, spring, NULL), "granbond_voigt_tangential", "out");
    EXPECT_NULL_ARG(granbond_voigt_rolling(NULL, &frame, fn, DT, angle, torque, &slip), "granbond_voigt_rolling",
                    "model");
    EXPECT_NULL_ARG(granbond_voigt_rolling(m, NULL, fn, DT, angle, torque, &slip), "granbond_voigt_rolling",
                    "frame");
    EXPECT_NULL_ARG(granbond_voigt_rolling(m, &frame, fn, DT, NULL, torque, &slip), "granbond_voigt_rolling",
                    "angle");
    EXPECT_NULL_ARG(granbond_voigt_rolling(m, &frame, fn, DT, angle, NULL, &slip), "granbond_voigt_rolling",
                    "torque_i");
    EXPECT_NULL_ARG(granbond_voigt_rolling(m, &frame, fn, DT, angle, torque, NULL), "granbond_voigt_rolling",
                    "slip");

    granbond_voigt_model_free(m);
    return 0;
}

/* ------------------------------------------------------------------------ */
/* Error state and freeing                                                   */
/* ------------------------------------------------------------------------ */

static int test_error_state_and_free(void)
{
    GbBondParams p = bond_fixture();
    GbBondModel *m = NULL;
    GbLayout l = caller_layout();

    /* A parameter failure, then a success: the error is cleared. */
    p.k_fn1 = -1.0;
    EXPECT(granbond_bond_model_new(&p, &m), GB_STATUS_INVALID_PARAMETER, "granbond_bond_model_new(k_fn1 = -1)");
    CHECK(granbond_last_error_parameter() == (int32_t)bond_field_id("k_fn1"), "parameter id set");
    CHECK(granbond_last_error_message()[0] != '\0', "message set");
    /* Reading the error does not clear it. */
    CHECK(granbond_last_error_parameter() == (int32_t)bond_field_id("k_fn1"), "parameter id still set");
    /* Functions without a status leave it alone. */
    CHECK(granbond_abi_version() == GRANBOND_ABI_VERSION && granbond_bond_parameter_count() == N_BOND_FIELDS &&
              granbond_state_len(GB_STATE_KIND_BOND) == GRANBOND_BOND_STATE_LEN,
          "abi_version, parameter_count, state_len");
    CHECK(granbond_last_error_parameter() == (int32_t)bond_field_id("k_fn1") &&
              granbond_last_error_message()[0] != '\0',
          "error unchanged by functions without a status");
    EXPECT_OK(granbond_check_layout(&l), "granbond_check_layout after a failure");
    CHECK(strcmp(granbond_last_error_message(), "") == 0, "granbond_last_error_message() = \"\" after a success");
    CHECK(granbond_last_error_parameter() == -1, "granbond_last_error_parameter() = -1 after a success");

    /* A non-parameter failure reports no parameter id. */
    EXPECT(granbond_bond_model_new(&p, &m), GB_STATUS_INVALID_PARAMETER, "granbond_bond_model_new(k_fn1 = -1)");
    EXPECT_NULL_ARG(granbond_check_layout(NULL), "granbond_check_layout", "expected");

    /* Freeing NULL is a no-op. */
    granbond_bond_model_free(NULL);
    CHECK(1, "granbond_bond_model_free(NULL) returns");
    granbond_voigt_model_free(NULL);
    CHECK(1, "granbond_voigt_model_free(NULL) returns");
    return 0;
}

int main(void)
{
    int failed = test_version_and_layout() || test_state_layout() || test_parameter_tables() || test_bond_params() ||
                 test_bond_create_and_force() || test_bond_errors() || test_bond_batch() || test_bond_indexed_results() ||
                 test_bond_indexed() ||
                 test_bond_break() ||
                 test_wall_bond() || test_bond_limits() || test_run_checks() || test_voigt_params() || test_voigt_contact() ||
                 test_voigt_batch() || test_voigt_plane() || test_voigt_timestep() || test_contact_frames() || test_voigt_parts() ||
                 test_error_state_and_free();
    if (failed) {
        printf("abi_harness: FAILED after %d checks\n", n_checks);
        return 1;
    }
    printf("abi_harness: all %d checks passed\n", n_checks);
    return 0;
}
