// The columns of the per-bond local output of both engines (LAMMPS
// `compute granbond/local`, LIGGGHTS `compute pair/gran/local/bond`), chosen
// by keyword: `id` (both atom ids), `pos` (both centres), every field the
// core names (granbond_bond_field_info), `all` for all of those fields, and
// the raw slots of the bond's record: `state` (the bond state, in the core's
// order) and `output` (the loads of the latest force pass as the core files
// them, GB_STATE_KIND_BOND_OUTPUT).
// The core computes the fields (granbond_bond_fields); this only picks
// columns, so a field the core gains is a keyword in both engines.
#ifndef GRANBOND_BOND_COLUMNS_H
#define GRANBOND_BOND_COLUMNS_H

#include "granbond.h"

#include <string>
#include <vector>

namespace granbond {

class BondColumns {
public:
    // `storeEnergy`: the engine's bonds live in the core's bond store, whose
    // per-bond energies (granbond_bond_energy_field_info) are keywords too.
    explicit BondColumns(bool storeEnergy = false) :
        fields_(granbond_bond_field_count(), 0.0), storeEnergy_(storeEnergy)
    {}

    // Reads the keywords; returns what is wrong (naming the keyword), or an
    // empty string.
    std::string parse(int narg, char **arg)
    {
        columns_.clear();
        if (narg < 1) return "no keyword (known: " + known() + ")";
        for (int k = 0; k < narg; k++) {
            const std::string word = arg[k];
            if (word == "id") {
                columns_.push_back(Column{kIdI, 0});
                columns_.push_back(Column{kIdJ, 0});
            } else if (word == "pos") {
                for (int c = 0; c < 6; c++) columns_.push_back(Column{kPos, c});
            } else if (word == "state") {
                for (int c = 0; c < GRANBOND_BOND_STATE_LEN; c++) columns_.push_back(Column{kRecord, c});
            } else if (word == "output") {
                for (int c = 0; c < GRANBOND_BOND_OUTPUT_LEN; c++)
                    columns_.push_back(Column{kRecord, GRANBOND_BOND_STATE_LEN + c});
            } else if (word == "all") {
                for (size_t f = 0; f < fields_.size(); f++) columns_.push_back(Column{kField, static_cast<int>(f)});
            } else if (storeEnergy_ && energyField(word) >= 0) {
                columns_.push_back(Column{kEnergy, energyField(word)});
            } else {
                const int f = field(word);
                if (f < 0) return "unknown keyword '" + word + "' (known: " + known() + ")";
                columns_.push_back(Column{kField, f});
            }
        }
        return std::string();
    }

    // LIGGGHTS-INL's columns 10-27 of `compute pair/gran/local/bond`
    // without keywords: the force on i, its normal and tangential parts,
    // the torque on i, its normal and tangential parts (fields of the
    // core). Returns what is wrong, or an empty string.
    std::string parseInlLoads()
    {
        static const char *const words[] = {
            "force_x",         "force_y",         "force_z",         "force_normal_x",      "force_normal_y",
            "force_normal_z",  "force_tangential_x", "force_tangential_y", "force_tangential_z", "torque_x",
            "torque_y",        "torque_z",        "torque_normal_x", "torque_normal_y",     "torque_normal_z",
            "torque_tangential_x", "torque_tangential_y", "torque_tangential_z"};
        std::vector<char *> arg;
        for (const char *w : words) arg.push_back(const_cast<char *>(w));
        return parse(static_cast<int>(arg.size()), arg.data());
    }

    size_t size() const { return columns_.size(); }

    // Whether a column is one of the bond store's energies.
    bool wantsEnergy() const
    {
        for (const Column &c : columns_)
            if (c.kind == kEnergy) return true;
        return false;
    }

    // The row of one bond: its model and record as sphere i sees it (the
    // state, then the output of the latest force pass as
    // granbond_bond_output_store writes it), the spheres' ids and centres,
    // and (where wantsEnergy()) its energies from the store
    // (granbond_bond_store_bond_energy). On failure the core's message says
    // why.
    GbStatus row(const GbBondModel *model, const double *record, double tag_i, double tag_j,
                 const double *x_i, const double *x_j, double *out, const double *energy = nullptr)
    {
        const GbStatus s = granbond_bond_fields(model, record, x_i, x_j, fields_.data());
        if (s != GB_STATUS_OK) return s;
        for (size_t c = 0; c < columns_.size(); c++) {
            const Column &col = columns_[c];
            switch (col.kind) {
            case kIdI: out[c] = tag_i; break;
            case kIdJ: out[c] = tag_j; break;
            case kPos: out[c] = col.index < 3 ? x_i[col.index] : x_j[col.index - 3]; break;
            case kRecord: out[c] = record[col.index]; break;
            case kEnergy: out[c] = energy ? energy[col.index] : 0.0; break;
            default: out[c] = fields_[col.index]; break;
            }
        }
        return GB_STATUS_OK;
    }

    // The position of field `name` in the core's table, or -1.
    static int field(const std::string &name)
    {
        const size_t n = granbond_bond_field_count();
        for (size_t f = 0; f < n; f++) {
            const char *fname = nullptr, *unit = nullptr, *description = nullptr;
            if (granbond_bond_field_info(f, &fname, &unit, &description) == GB_STATUS_OK && name == fname)
                return static_cast<int>(f);
        }
        return -1;
    }

    // The position of energy field `name` in the core's table, or -1.
    static int energyField(const std::string &name)
    {
        const size_t n = granbond_bond_energy_field_count();
        for (size_t f = 0; f < n; f++) {
            const char *fname = nullptr, *unit = nullptr, *description = nullptr;
            if (granbond_bond_energy_field_info(f, &fname, &unit, &description) == GB_STATUS_OK && name == fname)
                return static_cast<int>(f);
        }
        return -1;
    }

    std::string known() const
    {
        std::string s = "id pos state output all";
        const size_t n = granbond_bond_field_count();
        for (size_t f = 0; f < n; f++) {
            const char *fname = nullptr, *unit = nullptr, *description = nullptr;
            if (granbond_bond_field_info(f, &fname, &unit, &description) == GB_STATUS_OK) s += std::string(" ") + fname;
        }
        const size_t ne = storeEnergy_ ? granbond_bond_energy_field_count() : 0;
        for (size_t f = 0; f < ne; f++) {
            const char *fname = nullptr, *unit = nullptr, *description = nullptr;
            if (granbond_bond_energy_field_info(f, &fname, &unit, &description) == GB_STATUS_OK)
                s += std::string(" ") + fname;
        }
        return s;
    }

private:
    enum Kind { kIdI, kIdJ, kPos, kRecord, kField, kEnergy };
    struct Column {
        Kind kind;
        int index;
    };
    std::vector<Column> columns_;
    std::vector<double> fields_;
    bool storeEnergy_;
};

}

#endif
