/*
 * The parameter structs: the library's parameter tables read row by row and
 * checked against the header's structs, setting by name and when a
 * parameter is read, the defaults, and every out-of-range value refused with
 * its parameter id and names.
 */

#include "harness.h"

#include <stdlib.h>

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

int test_parameter_tables(void)
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
    {
        /* what is set by name reads back by row, as restart files hold it */
        double back = 0.0;
        EXPECT_OK(granbond_bond_params_set(&p, "k_fn1", 2.5e9), "set k_fn1 = 2.5e9");
        EXPECT_OK(granbond_bond_params_get(&p, 1, &back), "granbond_bond_params_get(k_fn1)");
        CHECK(back == 2.5e9, "k_fn1 reads back");
        EXPECT(granbond_bond_params_get(&p, N_BOND_FIELDS, &back), GB_STATUS_INVALID_ARGUMENT, "get(count)");
        {
            GbVoigtParams v;
            granbond_voigt_params_default(&v);
            EXPECT_OK(granbond_voigt_params_get(&v, 0, &back), "granbond_voigt_params_get(row 0)");
            EXPECT(granbond_voigt_params_get(&v, N_VOIGT_FIELDS, &back), GB_STATUS_INVALID_ARGUMENT,
                   "voigt get(count)");
        }
    }
    EXPECT(granbond_bond_params_set(&p, "damping", 0.5), GB_STATUS_INVALID_PARAMETER, "set damping = 0.5");
    EXPECT(granbond_bond_params_set(&p, "create_step", 2.5), GB_STATUS_INVALID_PARAMETER, "set create_step = 2.5");
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

size_t bond_field_id(const char *keyword)
{
    size_t i;
    for (i = 0; i < N_BOND_FIELDS; i++)
        if (strcmp(BOND_FIELDS[i].keyword, keyword) == 0)
            return i;
    return (size_t)-1;
}

size_t bond_field_count(void)
{
    return N_BOND_FIELDS;
}

static double *double_field(void *params, size_t offset)
{
    return (double *)(void *)((char *)params + offset);
}

static int32_t *int32_field(void *params, size_t offset)
{
    return (int32_t *)(void *)((char *)params + offset);
}

/* The names of row `id` of a table, from its GbParameterInfo. */
static GbStatus row_names(GbStatus (*info)(size_t, GbParameterInfo *), size_t id, const char **keyword,
                          const char **liggghts_name)
{
    GbParameterInfo row;
    GbStatus status = info(id, &row);
    if (status == GB_STATUS_OK) {
        *keyword = row.keyword;
        *liggghts_name = row.liggghts_name;
    }
    return status;
}

/* model_new refuses `p`: INVALID_PARAMETER, *model reset to NULL, the
 * parameter id of `keyword`, its names (and `also`, unless NULL) in the
 * message, and the same names from granbond_bond_parameter_info. */
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
    EXPECT_OK(row_names(granbond_bond_parameter_info, (size_t)reported, &kw, &lg),
              say("granbond_bond_parameter_info(%d)", (int)reported));
    CHECK(kw != NULL && strcmp(kw, keyword) == 0, say("parameter %d is keyword \"%s\"", (int)reported, keyword));
    CHECK(lg != NULL && strcmp(lg, BOND_FIELDS[id].liggghts) == 0,
          say("parameter %d is LIGGGHTS \"%s\"", (int)reported, BOND_FIELDS[id].liggghts));
    return 0;
}

int test_bond_params(void)
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

    /* Defaults in a unit style: the smoothing velocities are 1e-5 m/s and
       1e-3 rad/s in its units; lj has none, so smooth damping needs them. */
    EXPECT_OK(granbond_bond_params_default_in_units("micro", 0, &p), "granbond_bond_params_default_in_units(micro)");
    CHECK(fabs(p.smooth_velocity - 1e-5) < 1e-20 && fabs(p.smooth_angular_velocity - 1e-9) < 1e-24,
          "micro: 1e-5 um/us and 1e-9 rad/us");
    EXPECT_OK(granbond_bond_params_default_in_units("cgs", 0, &p), "granbond_bond_params_default_in_units(cgs)");
    CHECK(fabs(p.smooth_velocity - 1e-3) < 1e-18 && p.smooth_angular_velocity == 1e-3, "cgs: 1e-3 cm/s, 1e-3 rad/s");
    EXPECT_OK(granbond_bond_params_default_in_units("lj", 0, &p), "granbond_bond_params_default_in_units(lj)");
    CHECK(isnan(p.smooth_velocity) && isnan(p.smooth_angular_velocity), "lj: no smoothing velocities");
    EXPECT_OK(granbond_bond_model_new(&p, &m), "granbond_bond_model_new(lj defaults, smooth damping off)");
    granbond_bond_model_free(m);
    m = NULL;
    p.damping_smooth = 1;
    if (expect_bond_refused(&p, "smooth_velocity", NULL, "lj defaults with smooth damping"))
        return 1;
    /* The linear bond's defaults: its law, and the contact going on under
       its bonds (its law keeps the contact's loads there). */
    EXPECT_OK(granbond_bond_params_default_in_units("si", 1, &p), "granbond_bond_params_default_in_units(si, linear)");
    CHECK(p.linear == 1 && p.contact_under_bond == 1 && p.smooth_velocity == 1e-5,
          "the linear bond: linear and contact_under_bond on, the units' defaults");
    EXPECT_OK(granbond_bond_params_default_in_units("si", 0, &p), "granbond_bond_params_default_in_units(si)");
    CHECK(p.linear == 0 && p.contact_under_bond == 0, "bond/nonlinear: the contact held under the bond");
    EXPECT(granbond_bond_params_default_in_units(NULL, 0, &p), GB_STATUS_NULL_POINTER,
           "granbond_bond_params_default_in_units(NULL units)");
    /* Where the deck does not give contact_under_bond, the law says: on
       under a law that keeps some of the contact's loads (INL's code, the
       linear bond), off where the bond replaces the contact. */
    p.contact_under_bond = 1;
    EXPECT_OK(granbond_bond_params_contact_under_bond_by_law(&p), "granbond_bond_params_contact_under_bond_by_law");
    CHECK(p.contact_under_bond == 0, "bond/nonlinear by the law: the contact held under the bond");
    p.inl_compatible = 1;
    EXPECT_OK(granbond_bond_params_contact_under_bond_by_law(&p), "granbond_bond_params_contact_under_bond_by_law(inl)");
    CHECK(p.contact_under_bond == 1, "inl_compatible by the law: the contact goes on under the bond");
    p.inl_compatible = 0;
    p.linear = 1;
    p.contact_under_bond = 0;
    EXPECT_OK(granbond_bond_params_contact_under_bond_by_law(&p), "granbond_bond_params_contact_under_bond_by_law(linear)");
    CHECK(p.contact_under_bond == 1, "the linear bond by the law: the contact goes on under the bond");
    EXPECT_OK(granbond_bond_params_default(&p), "granbond_bond_params_default");

    /* The parameter table: one row per field, in field order. */
    CHECK(granbond_bond_parameter_count() == N_BOND_FIELDS,
          say("granbond_bond_parameter_count() = %u = fields of GbBondParams", (unsigned)N_BOND_FIELDS));
    for (i = 0; i < N_BOND_FIELDS; i++) {
        EXPECT_OK(row_names(granbond_bond_parameter_info, i, &kw, &lg), say("granbond_bond_parameter_info(%u)", (unsigned)i));
        CHECK(kw != NULL && lg != NULL && strcmp(kw, BOND_FIELDS[i].keyword) == 0 &&
                  strcmp(lg, BOND_FIELDS[i].liggghts) == 0,
              say("parameter %u = %s / %s", (unsigned)i, BOND_FIELDS[i].keyword, BOND_FIELDS[i].liggghts));
    }
    EXPECT_OK(row_names(granbond_bond_parameter_info, bond_field_id("k_fn1"), &kw, &lg), "granbond_bond_parameter_info(k_fn1)");
    CHECK(strcmp(kw, "k_fn1") == 0 && strcmp(lg, "stiffnessPerUnitAreaK_fn1") == 0,
          "k_fn1 <-> stiffnessPerUnitAreaK_fn1");
    EXPECT(row_names(granbond_bond_parameter_info, N_BOND_FIELDS, &kw, &lg), GB_STATUS_INVALID_ARGUMENT,
           "granbond_bond_parameter_info(count)");
    EXPECT_MESSAGE("out of range");

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

    /* Every field: a value out of range is refused with its own id. A
       smoothing velocity may be NaN (no default in the unit style) where
       smooth damping does not read it. */
    for (i = 0; i < N_BOND_FIELDS; i++) {
        const struct field *f = &BOND_FIELDS[i];
        const int smoothing = strncmp(f->keyword, "smooth_", 7) == 0;
        p = base;
        if (f->type == F_DOUBLE) {
            if (smoothing)
                p.damping_smooth = 1;
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

    return 0;
}

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

int test_voigt_params(void)
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
        EXPECT_OK(row_names(granbond_voigt_parameter_info, i, &kw, &lg), say("granbond_voigt_parameter_info(%u)", (unsigned)i));
        CHECK(strcmp(kw, VOIGT_FIELDS[i].keyword) == 0 && strcmp(lg, VOIGT_FIELDS[i].liggghts) == 0,
              say("voigt parameter %u is %s (%s)", (unsigned)i, VOIGT_FIELDS[i].keyword, VOIGT_FIELDS[i].liggghts));
    }
    {
        const char *kw = NULL, *lg = NULL;
        EXPECT(row_names(granbond_voigt_parameter_info, N_VOIGT_FIELDS, &kw, &lg), GB_STATUS_INVALID_ARGUMENT,
               "granbond_voigt_parameter_info(count)");
    }

    return 0;
}

/* Every word of a phrase's `reads` and every keyword of its `sets` is a row
 * the table sets by name, with the phrase's value for `sets`; returns the
 * number of phrases, or -1. */
static int check_phrases(const char *what, GbStatus (*phrase)(size_t, GbPhrase *), void *params,
                         GbStatus (*set)(void *, const char *, double))
{
    GbPhrase p;
    size_t id;
    for (id = 0; phrase(id, &p) == GB_STATUS_OK; id++) {
        char words[256], *w;
        CHECK(p.words && p.follows && p.reads && p.sets, "a phrase's strings are set");
        CHECK(strlen(p.reads) < sizeof words && strlen(p.sets) < sizeof words, "a phrase fits the buffer");
        strcpy(words, p.reads);
        for (w = strtok(words, " "); w; w = strtok(NULL, " "))
            if (set(params, w, 0.0) != GB_STATUS_OK && set(params, w, 1.0) != GB_STATUS_OK) {
                fprintf(stderr, "%s phrase '%s' reads '%s', which its table lacks\n", what, p.words, w);
                return -1;
            }
        strcpy(words, p.sets);
        for (w = strtok(words, " "); w; w = strtok(NULL, " ")) {
            const char *value = strtok(NULL, " ");
            CHECK(value != NULL, "a phrase sets keyword and value pairs");
            EXPECT_OK(set(params, w, atof(value)), "a phrase's setting");
        }
    }
    EXPECT(phrase(id, &p), GB_STATUS_INVALID_ARGUMENT, "phrase past the last one");
    return (int)id;
}

int test_deck_phrases(void)
{
    GbBondParams b;
    GbVoigtParams v;
    GbPhrase p;
    GbContactPart part = GB_CONTACT_PART_ROLLING;
    int n;
    granbond_bond_params_default(&b);
    granbond_voigt_params_default(&v);
    n = check_phrases("bond", granbond_bond_phrase_info, &b, bond_set);
    CHECK(n > 0, "the bond has phrases");
    n = check_phrases("voigt", granbond_voigt_phrase_info, &v, voigt_set);
    CHECK(n > 0, "the voigt contact has phrases");
    EXPECT_OK(granbond_bond_phrase_info(0, &p), "bond phrase 0");
    CHECK(strcmp(p.words, "break distance") == 0 && strcmp(p.sets, "stress_break 0 bpm_break 0") == 0,
          "bond phrase 0: a break distance is the stress and BPM switches off");
    {
        size_t id, creation = 0, contact = 0;
        for (id = 0; id < granbond_bond_parameter_count(); id++) {
            creation += granbond_bond_parameter_sets_creation(id) == 1;
            contact += granbond_bond_parameter_sets_creation(id) == 2;
        }
        CHECK(creation == 3, "three rows say when bonds form");
        CHECK(contact == 1, "one row says what the contact does under the bond");
        CHECK(granbond_bond_parameter_sets_creation(granbond_bond_parameter_count()) == -1, "beyond the table: -1");
    }
    /* the values after the model's name: a phrase without words */
    EXPECT_OK(granbond_voigt_phrase_info(0, &p), "voigt phrase 0");
    CHECK(p.words[0] == '\0' && strncmp(p.reads, "k_n ", 4) == 0, "voigt's values start with k_n");
    EXPECT_OK(granbond_voigt_parameter_part(0, &part), "part of k_n");
    CHECK(part == GB_CONTACT_PART_NORMAL, "k_n is the normal part's");
    EXPECT_OK(granbond_voigt_parameter_part(5, &part), "part of k_r");
    CHECK(part == GB_CONTACT_PART_ROLLING, "k_r is the rolling part's");
    EXPECT(granbond_voigt_parameter_part(N_VOIGT_FIELDS, &part), GB_STATUS_INVALID_ARGUMENT, "part past the last row");
    {
        GbSubModel sub;
        EXPECT_OK(granbond_voigt_sub_model(GB_CONTACT_PART_NORMAL, &sub), "sub-model of the normal part");
        CHECK(strcmp(sub.words, "model voigt") == 0, "the normal part is model voigt");
        CHECK(sub.reads == ((1u << GB_CONTACT_PART_NORMAL) | (1u << GB_CONTACT_PART_TANGENTIAL)),
              "model voigt reads the normal and tangential parts");
        EXPECT_OK(granbond_voigt_sub_model(GB_CONTACT_PART_ROLLING, &sub), "sub-model of the rolling part");
        CHECK(strcmp(sub.words, "rolling_friction voigt") == 0 && sub.reads == 1u << GB_CONTACT_PART_ROLLING,
              "rolling_friction voigt reads its own part");
        EXPECT(granbond_voigt_sub_model(3, &sub), GB_STATUS_INVALID_ARGUMENT, "sub-model past the last part");
        EXPECT(granbond_voigt_sub_model(0, NULL), GB_STATUS_NULL_POINTER, "sub-model into NULL");
    }
    return 0;
}

int test_coeff_lines(void)
{
    const char *pair[] = {"voigt", "1e5", "0.1", "2e4", "0", "0.5", "rolling", "1", "0", "0.2", "0",
                          "bond/nonlinear", "break", "stress", "1e6", "2e6", "k_fn1", "3e4"};
    const char *twice[] = {"voigt", "1e5", "0.1", "2e4", "0", "0.5", "k_n", "2e5"};
    const char *creation[] = {"k_fn1", "3e4", "create_step", "5"};
    GbVoigtParams v;
    GbBondParams b;
    int32_t has_bond = -1;
    EXPECT_OK(granbond_pair_coeff_read("pair_coeff 1 2", pair, 18, "si", &v, &b, &has_bond), "a pair_coeff line");
    CHECK(has_bond == 1 && v.k_n == 1e5 && v.gamma_n == 0.1 && v.rolling == 1 && v.mu_r == 0.2,
          "the contact's values, rolling on");
    CHECK(b.stress_break == 1 && b.max_sigma == 1e6 && b.max_tau == 2e6 && b.k_fn1 == 3e4,
          "break stress sets the stress switch and both limits");
    EXPECT_OK(granbond_pair_coeff_read("pair_coeff 1 2", pair, 11, "si", &v, &b, &has_bond), "a contact alone");
    CHECK(has_bond == 0, "no bond clause");
    EXPECT(granbond_pair_coeff_read("pair_coeff 1 2", twice, 8, "si", &v, &b, &has_bond), GB_STATUS_INVALID_ARGUMENT,
           "k_n given twice");
    CHECK(strstr(granbond_last_error_message(), "pair_coeff 1 2 voigt: 'k_n 2e5' conflicts with 'voigt'") != NULL,
          say("the message names the command, the clause and both words: %s", granbond_last_error_message()));
    EXPECT_OK(granbond_bond_coeff_read("bond_coeff 3", creation, 2, &b), "a bond_coeff line");
    CHECK(b.k_fn1 == 3e4, "k_fn1 read");
    EXPECT(granbond_bond_coeff_read("bond_coeff 3", creation, 4, &b), GB_STATUS_INVALID_ARGUMENT,
           "bond_coeff refuses when bonds form");
    CHECK(strstr(granbond_last_error_message(), "bond_coeff 3 bond/nonlinear: 'create_step' says when bonds form") !=
              NULL,
          say("the message names the phrase: %s", granbond_last_error_message()));
    return 0;
}

int test_restart_rows(void)
{
    uint8_t rows[4096];
    size_t len = 0, need = 0;
    GbBondParams b, back;
    int32_t count = 0;
    granbond_bond_params_default(&b);
    b.k_fn1 = 1234.5;
    EXPECT_OK(granbond_bond_params_rows(&b, NULL, 0, &need), "the rows' length");
    EXPECT_OK(granbond_bond_params_rows(&b, rows, sizeof rows, &len), "the bond's rows");
    memcpy(&count, rows, sizeof count);
    CHECK(len == need && count == (int32_t)granbond_bond_parameter_count(), "one row a parameter");
    EXPECT(granbond_bond_params_rows(&b, rows, 8, &len), GB_STATUS_INVALID_ARGUMENT, "rows beyond the capacity");
    EXPECT_OK(granbond_bond_params_rows(&b, rows, sizeof rows, &len), "the bond's rows again");
    EXPECT_OK(granbond_bond_params_from_rows(rows, len, "bond type 2", &back), "rows read back");
    {
        size_t id, same = 0;
        for (id = 0; id < granbond_bond_parameter_count(); id++) {
            double x = 0.0, y = 1.0;
            granbond_bond_params_get(&b, id, &x);
            granbond_bond_params_get(&back, id, &y);
            same += x == y || (x != x && y != y);
        }
        CHECK(back.k_fn1 == 1234.5 && same == granbond_bond_parameter_count(), "the same parameters");
    }
    /* the last row left out: the file of another table */
    count -= 1;
    memcpy(rows, &count, sizeof count);
    EXPECT(granbond_bond_params_from_rows(rows, len, "bond type 2", &back), GB_STATUS_INVALID_ARGUMENT,
           "a row missing");
    CHECK(strstr(granbond_last_error_message(), "does not set") != NULL &&
              strstr(granbond_last_error_message(), "bond type 2") != NULL,
          say("the message names what is missing and where: %s", granbond_last_error_message()));
    return 0;
}

int test_liggghts_lines(void)
{
    const char *line[] = {"p", "all", "property/global", "maxSigmaBondnonlinear", "peratomtypepair", "2", "1e6", "inf", "1e6", "1e6"};
    const char *settings[] = {"contactUnderBond", "on", "contactUnderBond", "off"};
    int32_t infinite[10], ours = -1;
    EXPECT_OK(granbond_liggghts_property_line_check(line, 10, infinite, &ours), "a property line");
    CHECK(ours == 1 && infinite[7] == 1 && infinite[6] == 0, "a granbond property, its infinity flagged");
    EXPECT(granbond_liggghts_property_line_check(line, 9, infinite, &ours), GB_STATUS_INVALID_ARGUMENT,
           "a value missing");
    CHECK(strstr(granbond_last_error_message(), "peratomtypepair 2 needs 4 values, got 3") != NULL,
          say("the message counts the values: %s", granbond_last_error_message()));
    EXPECT_OK(granbond_liggghts_settings_check("pair_style gran", settings, 2), "a switch");
    EXPECT(granbond_liggghts_settings_check("pair_style gran", settings, 4), GB_STATUS_INVALID_ARGUMENT,
           "a switch given twice");
    EXPECT(granbond_liggghts_settings_check("pair_style gran", settings, 3), GB_STATUS_INVALID_ARGUMENT,
           "a switch without a value");
    return 0;
}
