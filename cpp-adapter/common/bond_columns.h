// The columns of the per-bond local output of both engines (LAMMPS
// `compute granbond/local`, LIGGGHTS `compute pair/gran/local/bond`): the
// core reads the keywords and fills each row from its field table
// (granbond_bond_columns_new, granbond_bond_columns_row), so a field the
// core gains is a keyword in both engines. This holds the core's columns.
#ifndef GRANBOND_BOND_COLUMNS_H
#define GRANBOND_BOND_COLUMNS_H

#include "core_message.h"
#include "granbond.h"

#include <string>

namespace granbond {

class BondColumns {
public:
    BondColumns() = default;
    BondColumns(const BondColumns &) = delete;
    BondColumns &operator=(const BondColumns &) = delete;
    ~BondColumns() { granbond_bond_columns_free(columns_); }

    // Reads the keywords (`inl`: none, LIGGGHTS-INL's columns after its
    // first nine); returns what is wrong (naming the keyword), or an empty
    // string.
    std::string parse(int narg, char **arg, bool inl = false)
    {
        granbond_bond_columns_free(columns_);
        columns_ = nullptr;
        int32_t energy = 0;
        if (granbond_bond_columns_new(arg, static_cast<size_t>(narg), inl ? 1 : 0, &columns_) != GB_STATUS_OK ||
            granbond_bond_columns_info(columns_, &size_, &energy) != GB_STATUS_OK)
            return coreReason();
        wantsEnergy_ = energy != 0;
        return std::string();
    }

    size_t size() const { return size_; }
    // Whether a column is one of the bond store's energies.
    bool wantsEnergy() const { return wantsEnergy_; }

    // The row of one bond into `out`: its model and record as sphere i
    // sees it (the state, then the output of the latest force pass as
    // granbond_bond_output_store writes it), the spheres' ids and centres,
    // its energies (granbond_bond_energy_field_count() values, read where
    // wantsEnergy()). On failure the core's message says why.
    GbStatus row(const GbBondModel *model, const double *record, double tag_i, double tag_j, const double *x_i,
                 const double *x_j, double *out, const double *energy) const
    {
        return granbond_bond_columns_row(columns_, model, record, energy, tag_i, tag_j, x_i, x_j, out);
    }

private:
    GbBondColumns *columns_ = nullptr;
    size_t size_ = 0;
    bool wantsEnergy_ = false;
};

}

#endif
