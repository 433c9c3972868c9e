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
#include <cstring>
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

// A table's rows as the core writes them (granbond_*_params_rows).
template<class P>
void writeRows(FILE *fp, GbStatus (*rows)(const P *, uint8_t *, size_t, size_t *), const P &params, Error *error)
{
    size_t len = 0;
    std::vector<uint8_t> buf;
    if (rows(&params, nullptr, 0, &len) == GB_STATUS_OK) buf.resize(len);
    if (buf.empty() || rows(&params, buf.data(), buf.size(), &len) != GB_STATUS_OK)
        error->one(FLERR, std::string("pair_style granbond: writing the restart file: ") + coreReason());
    fwrite(buf.data(), 1, buf.size(), fp);
}

// Rank 0 reads one table's rows as written, every rank gets them; a count
// or a name length out of bounds stops the reading there, and the core
// says the file is damaged.
std::vector<uint8_t> readRows(FILE *fp, int me, MPI_Comm world, Error *error)
{
    std::vector<uint8_t> rows;
    auto read = [&](size_t n) {
        rows.resize(rows.size() + n);
        utils::sfread(FLERR, rows.data() + rows.size() - n, 1, n, fp, nullptr, error);
    };
    if (me == 0) {
        int count = 0, length = 0;
        read(sizeof(int));
        std::memcpy(&count, rows.data(), sizeof(int));
        for (int k = 0; k < count && k < static_cast<int>(GRANBOND_RESTART_MAX_ROWS); k++) {
            read(sizeof(int));
            std::memcpy(&length, rows.data() + rows.size() - sizeof(int), sizeof(int));
            if (length <= 0 || length > static_cast<int>(GRANBOND_RESTART_MAX_KEYWORD)) break;
            read(static_cast<size_t>(length) + sizeof(double));
        }
    }
    unsigned long long size = rows.size();
    MPI_Bcast(&size, 1, MPI_UNSIGNED_LONG_LONG, 0, world);
    rows.resize(size);
    MPI_Bcast(rows.data(), static_cast<int>(size), MPI_BYTE, 0, world);
    return rows;
}

// The parameters the rows set (the core refuses a file of another table).
template<class P>
void setRows(GbStatus (*fromRows)(const uint8_t *, size_t, const char *, P *), const std::vector<uint8_t> &rows,
             P &params, const std::string &what, Error *error)
{
    if (fromRows(rows.data(), rows.size(), what.c_str(), &params) != GB_STATUS_OK) error->all(FLERR, coreReason());
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
            writeRows(fp, &granbond_voigt_params_rows, tp.voigt, error);
            writeRows(fp, &granbond_bond_params_rows, tp.bond, error);
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
            const std::string types = "atom types " + std::to_string(i) + " " + std::to_string(j);
            setRows(&granbond_voigt_params_from_rows, readRows(fp, me, world, error), tp.voigt, types, error);
            setRows(&granbond_bond_params_from_rows, readRows(fp, me, world, error), tp.bond, types, error);
            pairs_[at(i, j)] = tp;
            pairs_[at(j, i)] = tp;
            setflag[j][i] = 1;
            buildModel(i, j);
        }
}

// bond_style granbond's rows of a bond type (restart_rows.h).
void writeBondRows(FILE *fp, const GbBondParams &params, Error *error)
{
    writeRows(fp, &granbond_bond_params_rows, params, error);
}

void readBondRows(FILE *fp, GbBondParams &params, const std::string &what, int me, MPI_Comm world, Error *error)
{
    setRows(&granbond_bond_params_from_rows, readRows(fp, me, world, error), params, what, error);
}

}
}
