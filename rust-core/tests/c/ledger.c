/*
 * The ledger: counts as a row, the warnings the core composes from counts
 * summed over ranks, the break log's events, words and text, the per-bond
 * output columns, the thin periodic box check and the store check's
 * findings.
 */

#include "harness.h"

#include <stdlib.h>

static int test_counts_and_notices(void)
{
    GbStoreCounts counts;
    GbCheckReport report;
    double row[GRANBOND_COUNTS_ROW_LEN];
    const int64_t lost[4] = {2, 0, 1, 0}, none[4] = {0, 0, 0, 0}, negative[4] = {-1, 0, 0, 0};
    memset(&counts, 0, sizeof counts);
    counts.created = 9;
    counts.broken_tension = 2;
    counts.broken_shear = 1;
    counts.lost_no_model = 1;
    counts.intact = 5;
    EXPECT_OK(granbond_store_counts_row(&counts, row), "granbond_store_counts_row");
    CHECK(row[0] == 9 && row[1] == 3 && row[2] == 5 && row[4] == 2 && row[6] == 1 && row[7] == 1,
          "the row: created, broken, intact, by mode, lost");
    EXPECT_OK(granbond_ledger_notice(GRANBOND_NOTICE_PAIRS_LOST_LAMMPS, lost, 40, NULL, &report),
              "granbond_ledger_notice(pairs lost, LAMMPS)");
    CHECK(report.level == 1 && strstr(report.message, "pair granbond (bond/nonlinear): 3 bonds lost at step 40") &&
              strstr(report.message, "2 because their atom left the system"),
          say("the loss warning counts and names the causes: %s", report.message));
    EXPECT_OK(granbond_ledger_notice(GRANBOND_NOTICE_WALL_LOST_LIGGGHTS, lost, 40, "walls", &report),
              "granbond_ledger_notice(wall lost)");
    CHECK(strstr(report.message, "(wall walls): 3 wall bonds lost by step 40") != NULL, "the wall fix named");
    EXPECT_OK(granbond_ledger_notice(GRANBOND_NOTICE_RENUMBERED, none, 40, "s", &report), "granbond_ledger_notice(none)");
    CHECK(report.level == 0 && report.message[0] == 0, "no atom concerned: level 0, no message");
    EXPECT(granbond_ledger_notice(6, lost, 40, "s", &report), GB_STATUS_INVALID_ARGUMENT, "notice_id 6");
    EXPECT_MESSAGE("notice_id");
    EXPECT(granbond_ledger_notice(GRANBOND_NOTICE_RENUMBERED, negative, 40, "s", &report), GB_STATUS_INVALID_ARGUMENT,
           "a negative count");
    EXPECT_MESSAGE("counts");
    return 0;
}

static int test_break_log(void)
{
    GbBondParams p = bond_fixture();
    GbBondModel *m = NULL;
    GbBondOutput out;
    GbBreakEvent events[2];
    const double x_i[3] = {0.0, 0.0, 0.0}, x_j[3] = {2.0e-3, 0.0, 0.0};
    const char *const words[] = {"log", "all", "bond/breaklog", "breaks.txt", "every", "25"};
    const char *const bad[] = {"log", "all", "bond/breaklog", "breaks.txt", "every", "0"};
    char text[3 * GRANBOND_BREAK_LOG_LINE_LEN], small[8];
    int32_t every = 0;
    EXPECT_OK(new_bond_model(&p, &m) ? GB_STATUS_INVALID_ARGUMENT : GB_STATUS_OK, "the fixture's model");
    memset(&out, 0, sizeof out);
    out.delta = -1.0e-7;
    out.sigma = 2.0e7;
    out.break_mode = GB_BREAK_MODE_TENSION;
    EXPECT_OK(granbond_break_event(m, &out, x_i, x_j, 1.0e-3, 1.0e-3, 9.0, 4.0, 30.0, &events[0]),
              "granbond_break_event(pair)");
    CHECK(events[0].tag_i == 4.0 && events[0].tag_j == 9.0 && events[0].x[0] == 1.0e-3 &&
              events[0].mode == GB_BREAK_MODE_TENSION,
          "the smaller id first, the centre between the spheres");
    EXPECT_OK(granbond_break_event(m, &out, x_i, x_j, 1.0e-3, 0.0, 5.0, 0.0, 20.0, &events[1]),
              "granbond_break_event(wall)");
    CHECK(events[1].tag_j == 0.0 && events[1].x[0] == 2.0e-3, "a wall bond's centre is the wall point");
    EXPECT(granbond_break_event(m, &out, x_i, x_j, 0.0, 1.0e-3, 9.0, 4.0, 30.0, &events[0]), GB_STATUS_INVALID_ARGUMENT,
           "radius_i 0");
    EXPECT_OK(granbond_break_log_text(events, 2, 1, text, sizeof text), "granbond_break_log_text");
    CHECK(strncmp(text, "# step id_i id_j", 16) == 0 && strstr(text, "\n20 5 0 ") && strstr(text, "\n30 4 9 ") &&
              strstr(text, "\n20 5 0 ") < strstr(text, "\n30 4 9 "),
          say("the header, then the lines by step: %s", text));
    EXPECT(granbond_break_log_text(events, 2, 0, small, sizeof small), GB_STATUS_INVALID_ARGUMENT, "a short buffer");
    EXPECT_MESSAGE("capacity");
    events[0].step = 0.5;
    EXPECT(granbond_break_log_text(events, 2, 0, text, sizeof text), GB_STATUS_INVALID_ARGUMENT, "a step of 0.5");
    EXPECT_MESSAGE("step");
    EXPECT_OK(granbond_break_log_words(words, 6, &every), "granbond_break_log_words");
    CHECK(every == 25, "every 25");
    EXPECT(granbond_break_log_words(bad, 6, &every), GB_STATUS_INVALID_ARGUMENT, "every 0");
    EXPECT_MESSAGE("every must be an integer >= 1, got '0'");
    granbond_bond_model_free(m);
    return 0;
}

static int test_columns(void)
{
    GbBondParams p = bond_fixture();
    GbBondModel *m = NULL;
    GbBondColumns *cols = NULL;
    const char *const words[] = {"id", "r0", "energy_stored"};
    const char *const bad[] = {"id", "radius"};
    double record[GRANBOND_BOND_STATE_LEN + GRANBOND_BOND_OUTPUT_LEN], energy[16], row[4];
    const double x_i[3] = {0.0, 0.0, 0.0}, x_j[3] = {2.0e-3, 0.0, 0.0};
    size_t count = 0;
    int32_t wants = 0;
    EXPECT_OK(new_bond_model(&p, &m) ? GB_STATUS_INVALID_ARGUMENT : GB_STATUS_OK, "the fixture's model");
    CHECK(granbond_bond_energy_field_count() <= 16, "room for the energies");
    memset(record, 0, sizeof record);
    memset(energy, 0, sizeof energy);
    if (create_bond(m, record))
        return 1;
    energy[0] = 7.0;
    EXPECT_OK(granbond_bond_columns_new(words, 3, 0, &cols), "granbond_bond_columns_new");
    EXPECT_OK(granbond_bond_columns_info(cols, &count, &wants), "granbond_bond_columns_info");
    CHECK(count == 4 && wants == 1, "id is two columns; an energy is asked for");
    EXPECT_OK(granbond_bond_columns_row(cols, m, record, energy, 3.0, 8.0, x_i, x_j, row), "granbond_bond_columns_row");
    CHECK(row[0] == 3.0 && row[1] == 8.0 && row[2] == record[0] && row[3] == 7.0,
          say("ids, the rest length, the stored energy: %g %g %g %g", row[0], row[1], row[2], row[3]));
    EXPECT(granbond_bond_columns_row(cols, m, record, energy, 3.0, 8.0, x_i, x_i, row), GB_STATUS_INVALID_ARGUMENT,
           "coincident centres");
    granbond_bond_columns_free(cols);
    cols = NULL;
    EXPECT_OK(granbond_bond_columns_new(NULL, 0, 1, &cols), "granbond_bond_columns_new(INL)");
    EXPECT_OK(granbond_bond_columns_info(cols, &count, &wants), "granbond_bond_columns_info(INL)");
    CHECK(count == 18 + GRANBOND_BOND_STATE_LEN && wants == 0, "INL: the loads in their parts, then the state");
    granbond_bond_columns_free(cols);
    EXPECT(granbond_bond_columns_new(bad, 2, 0, &cols), GB_STATUS_INVALID_ARGUMENT, "an unknown keyword");
    EXPECT_MESSAGE("unknown keyword 'radius' (known: id pos state output all");
    granbond_bond_columns_free(NULL);
    granbond_bond_model_free(m);
    return 0;
}

static int test_box_and_store_checks(void)
{
    GbCheckReport report;
    const int32_t periodic[3] = {1, 1, 1};
    const double length[3] = {1.0, 1.0, 3.0e-3};
    double keys[6] = {4.0, 9.0, 1.0, 2.0, 4.0, 9.0};
    const int64_t balanced[4] = {5, 1, 3, 1}, unbalanced[4] = {5, 1, 3, 0};
    EXPECT_OK(granbond_thin_periodic_box_check("pair granbond", 3, periodic, length, 2.0e-3, 5.0e-4, -1, &report),
              "granbond_thin_periodic_box_check");
    CHECK(report.level == 1 && strstr(report.message, "pair granbond: the periodic box is 0.003 long in z"),
          say("a box shorter than twice the reach: %s", report.message));
    EXPECT_OK(granbond_thin_periodic_box_check("s", 2, periodic, length, 2.0e-3, 5.0e-4, -1, &report),
              "granbond_thin_periodic_box_check(2d)");
    CHECK(report.level == 0, "a 2d run has no images in z");
    EXPECT(granbond_thin_periodic_box_check("s", 4, periodic, length, 2.0e-3, 5.0e-4, -1, &report),
           GB_STATUS_INVALID_ARGUMENT, "dimension 4");
    EXPECT_OK(granbond_store_check_findings(keys, 3, balanced, 0, &report), "granbond_store_check_findings");
    CHECK(report.level == 1 && strcmp(report.message, "the bond of atoms 4 and 9 is stored twice") == 0,
          say("a bond held twice: %s", report.message));
    EXPECT_OK(granbond_store_check_findings(keys, 2, unbalanced, 1, &report), "granbond_store_check_findings(walls)");
    CHECK(strcmp(report.message, "5 wall bonds created or restored, 1 broken, 3 intact, 0 lost") == 0,
          say("counts that do not balance: %s", report.message));
    EXPECT_OK(granbond_store_check_findings(keys, 2, balanced, 0, &report), "granbond_store_check_findings(well)");
    CHECK(report.level == 0, "nothing wrong");
    return 0;
}

static int test_store_record(void)
{
    GbStoreCounts counts, back;
    GbEnergySums energy, energy_back;
    uint8_t record[GRANBOND_STORE_RECORD_LEN];
    int64_t layout = 0;
    memset(&counts, 0, sizeof counts);
    counts.created = 7;
    counts.lost_id_reused = 2;
    counts.intact = 5;
    energy.damping = 1.5e-9;
    energy.hysteresis = 2.5e-10;
    energy.released = 0.0;
    EXPECT_OK(granbond_store_record_write(&counts, &energy, record, sizeof record), "granbond_store_record_write");
    EXPECT_OK(granbond_store_record_read(record, &back, &energy_back), "granbond_store_record_read");
    CHECK(memcmp(&counts, &back, sizeof counts) == 0 && memcmp(&energy, &energy_back, sizeof energy) == 0,
          "the record brings back the counts and energies bit for bit");
    memcpy(&layout, record, sizeof layout);
    CHECK(layout == (int64_t)(GRANBOND_STORE_RECORD_LEN - sizeof layout), "the record leads with its length");
    EXPECT(granbond_store_record_write(&counts, &energy, record, 8), GB_STATUS_INVALID_ARGUMENT, "no room");
    layout = GRANBOND_STATE_LAYOUT_VERSION + 1;
    memcpy(record + GRANBOND_STORE_RECORD_LEN - sizeof layout, &layout, sizeof layout);
    EXPECT(granbond_store_record_read(record, &back, &energy_back), GB_STATUS_INVALID_ARGUMENT, "another layout");
    EXPECT_MESSAGE("written with bond state layout");
    layout = 96;
    memcpy(record, &layout, sizeof layout);
    EXPECT(granbond_store_record_read(record, &back, &energy_back), GB_STATUS_INVALID_ARGUMENT, "an older record");
    EXPECT_MESSAGE("an older bond state layout");
    return 0;
}

int test_ledger(void)
{
    return test_counts_and_notices() || test_break_log() || test_columns() || test_box_and_store_checks() ||
           test_store_record();
}
