// pair_style granbond in restart files: the settings of each type pair as
// (keyword, value) rows of the core's parameter tables, so that a file
// names what it sets. A file that sets a keyword this granbond does not
// know, or leaves out one it does, is refused with the keywords named; a
// file of another state layout, or one that holds the settings as raw
// bytes, is refused before anything is read from it.
#include "pair_granbond.h"
#include "core_message.h"
#include "restart_rows.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "utils.h"

#include <cstdio>
#include <string>
#include <vector>

using namespace LAMMPS_NS;

namespace granbond {
namespace lammps {

namespace {

// Written ahead of the settings: the raw-bytes layout of earlier files, and
// the rows by name of this one.
const int kRawMagic = 0x67626e64;      // "gbnd"
const int kByNameMagic = 0x67626e32;   // "gbn2"

// One table's rows, read from the core, written and read as (length, name,
// value).
struct Table {
    const char *model;
    size_t count;
    GbStatus (*info)(size_t, GbParameterInfo *);
    GbStatus (*get)(const void *, size_t, double *);
    GbStatus (*set)(void *, const char *, double);
};

GbStatus bondGet(const void *p, size_t id, double *v) { return granbond_bond_params_get(static_cast<const GbBondParams *>(p), id, v); }
GbStatus bondSet(void *p, const char *name, double v) { return granbond_bond_params_set(static_cast<GbBondParams *>(p), name, v); }
GbStatus voigtGet(const void *p, size_t id, double *v) { return granbond_voigt_params_get(static_cast<const GbVoigtParams *>(p), id, v); }
GbStatus voigtSet(void *p, const char *name, double v) { return granbond_voigt_params_set(static_cast<GbVoigtParams *>(p), name, v); }

Table bondTable() { return {"bond/nonlinear", granbond_bond_parameter_count(), granbond_bond_parameter_info, bondGet, bondSet}; }
Table voigtTable() { return {"voigt", granbond_voigt_parameter_count(), granbond_voigt_parameter_info, voigtGet, voigtSet}; }

void writeRows(FILE *fp, const Table &t, const void *params, Error *error)
{
    const int count = static_cast<int>(t.count);
    fwrite(&count, sizeof(int), 1, fp);
    for (size_t id = 0; id < t.count; id++) {
        GbParameterInfo info;
        double value = 0.0;
        if (t.info(id, &info) != GB_STATUS_OK || t.get(params, id, &value) != GB_STATUS_OK)
            error->one(FLERR, std::string("pair_style granbond: writing the restart file: ") + coreReason());
        const std::string name = info.keyword;
        const int length = static_cast<int>(name.size());
        fwrite(&length, sizeof(int), 1, fp);
        fwrite(name.data(), 1, name.size(), fp);
        fwrite(&value, sizeof(double), 1, fp);
    }
}

// Rank 0 reads; every rank gets the rows.
struct Row {
    std::string name;
    double value;
};

std::vector<Row> readRows(FILE *fp, int me, MPI_Comm world, Error *error)
{
    int count = 0;
    if (me == 0) utils::sfread(FLERR, &count, sizeof(int), 1, fp, nullptr, error);
    MPI_Bcast(&count, 1, MPI_INT, 0, world);
    if (count < 0 || count > 10000)
        error->all(FLERR, "granbond: the restart file is damaged (a table of " + std::to_string(count) +
                              " parameters)");
    std::vector<Row> rows(count);
    for (Row &r : rows) {
        int length = 0;
        if (me == 0) utils::sfread(FLERR, &length, sizeof(int), 1, fp, nullptr, error);
        MPI_Bcast(&length, 1, MPI_INT, 0, world);
        if (length <= 0 || length > 200)
            error->all(FLERR, "granbond: the restart file is damaged (a parameter name of " +
                                  std::to_string(length) + " characters)");
        std::vector<char> name(length);
        if (me == 0) utils::sfread(FLERR, name.data(), 1, length, fp, nullptr, error);
        MPI_Bcast(name.data(), length, MPI_CHAR, 0, world);
        if (me == 0) utils::sfread(FLERR, &r.value, sizeof(double), 1, fp, nullptr, error);
        MPI_Bcast(&r.value, 1, MPI_DOUBLE, 0, world);
        r.name.assign(name.begin(), name.end());
    }
    return rows;
}

// The rows set on defaults: every keyword of the table once, no other.
void setRows(const Table &t, const std::vector<Row> &rows, void *params, const std::string &types, Error *error)
{
    std::vector<char> seen(t.count, 0);
    for (const Row &r : rows) {
        size_t id = t.count;
        for (size_t k = 0; k < t.count && id == t.count; k++) {
            GbParameterInfo info;
            if (t.info(k, &info) == GB_STATUS_OK && r.name == info.keyword) id = k;
        }
        if (id == t.count)
            error->all(FLERR, "granbond: the restart file sets '" + r.name + "' for " + types + " (" +
                                  t.model + "), a keyword this granbond does not know; write the restart file "
                                  "again with this granbond");
        seen[id] = 1;
        if (t.set(params, r.name.c_str(), r.value) != GB_STATUS_OK)
            error->all(FLERR, "granbond: the restart file's " + types + " (" + t.model +
                                  "): " + coreReason());
    }
    std::string missing;
    for (size_t k = 0; k < t.count; k++) {
        GbParameterInfo info;
        if (!seen[k] && t.info(k, &info) == GB_STATUS_OK) missing += std::string(missing.empty() ? "" : " ") + info.keyword;
    }
    if (!missing.empty())
        error->all(FLERR, "granbond: the restart file does not set " + missing + " for " + types + " (" +
                              t.model + "), which this granbond reads; write the restart file again with this "
                              "granbond");
}

}

void PairGranbond::write_restart(FILE *fp)
{
    const int head[2] = {kByNameMagic, static_cast<int>(GRANBOND_STATE_LAYOUT_VERSION)};
    fwrite(head, sizeof(int), 2, fp);
    const int n = atom->ntypes;
    for (int i = 1; i <= n; i++)
        for (int j = i; j <= n; j++) {
            fwrite(&setflag[i][j], sizeof(int), 1, fp);
            if (!setflag[i][j]) continue;
            const TypePair &tp = pairs_[at(i, j)];
            // the second flag repeats the row contact_under_bond, which the
            // bond's rows restore
            const int flags[2] = {tp.hasBond, tp.bond.contact_under_bond};
            fwrite(flags, sizeof(int), 2, fp);
            writeRows(fp, voigtTable(), &tp.voigt, error);
            writeRows(fp, bondTable(), &tp.bond, error);
        }
}

void PairGranbond::read_restart(FILE *fp)
{
    allocate();
    const int n = atom->ntypes;
    const int me = comm->me;
    int head[2] = {0, 0};
    if (me == 0) utils::sfread(FLERR, head, sizeof(int), 2, fp, nullptr, error);
    MPI_Bcast(head, 2, MPI_INT, 0, world);
    if (head[0] == kRawMagic)
        error->all(FLERR, "pair_style granbond: this restart file was written by an older granbond that kept "
                          "each type pair's settings as raw bytes, which this granbond cannot read safely. Rerun "
                          "the original deck with this granbond to write a new restart file");
    if (head[0] != kByNameMagic)
        error->all(FLERR, "pair_style granbond: this restart file was written by a granbond whose bond and "
                          "contact state has an older layout (no state layout version); its per-pair histories "
                          "cannot be read. Rerun "
                          "the original deck with this granbond to write a new restart file");
    if (head[1] != static_cast<int>(GRANBOND_STATE_LAYOUT_VERSION))
        error->all(FLERR, "pair_style granbond: this restart file has state layout version " +
                              std::to_string(head[1]) + ", this granbond uses version " +
                              std::to_string(GRANBOND_STATE_LAYOUT_VERSION) +
                              "; its per-pair histories cannot be read. Rerun the original deck with this "
                              "granbond to write a new restart file");
    for (int i = 1; i <= n; i++)
        for (int j = i; j <= n; j++) {
            if (me == 0) utils::sfread(FLERR, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
            MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
            if (!setflag[i][j]) continue;
            int flags[2] = {0, 0};
            if (me == 0) utils::sfread(FLERR, flags, sizeof(int), 2, fp, nullptr, error);
            MPI_Bcast(flags, 2, MPI_INT, 0, world);
            TypePair tp;
            tp.hasBond = flags[0];
            granbond_voigt_params_default(&tp.voigt);
            granbond_bond_params_default(&tp.bond);
            const std::string types = "atom types " + std::to_string(i) + " " + std::to_string(j);
            setRows(voigtTable(), readRows(fp, me, world, error), &tp.voigt, types, error);
            setRows(bondTable(), readRows(fp, me, world, error), &tp.bond, types, error);
            pairs_[at(i, j)] = tp;
            pairs_[at(j, i)] = tp;
            setflag[j][i] = 1;
            buildModel(i, j);
        }
}

// bond_style granbond's rows of a bond type (restart_rows.h).
void writeBondRows(FILE *fp, const GbBondParams &params, Error *error) { writeRows(fp, bondTable(), &params, error); }

void readBondRows(FILE *fp, GbBondParams &params, const std::string &what, int me, MPI_Comm world, Error *error)
{
    granbond_bond_params_default(&params);
    setRows(bondTable(), readRows(fp, me, world, error), &params, what, error);
}

}
}
