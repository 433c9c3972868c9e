// The index of a pass's bonded pairs of one bond model: where each bond's
// pair record lies, its two atoms, and the engine's flag of the pair. Each
// pass hands the whole index to the core (granbond_bond_sweep), which
// applies the pass rule to every bond in index order; the contact loop
// passes over a swept pair at once. The same in both adapters.
//
// The index holds pointers into the engine's history pages and indices into
// its atom arrays, so it is rebuilt whenever the engine rebuilds its
// neighbour lists (the pages move, atoms migrate); a bond that forms in a
// pass is added to it. Records are keyed by the neighbour list, not by atom
// IDs, so an ID handed out again cannot lead a bond to another pair
// (fix_granbond_atoms.h forgets such records before any index is built).
//
// Where the adapter can write the bonds back before the engine moves its
// records (the history fixes' pre_exchange), the core steps copies
// of the bonds' states side by side in index order (`rows`): the engine's
// pages hold a record for every neighbour, so the bonds' records lie apart
// there, and a pass would wait on memory for each. The engine's record
// stays the bond's home: its bond state copied into the row when the index
// is built, written back when the bond breaks and before the engine reads
// or moves the records.
//
// The index keeps each bond's output of its latest pass (`outs`), which the
// core writes anyway for the loads to reach the atoms. A force pass stores
// the loads in the records only where the engine reads them within the pass
// (`pass.keep_loads`); otherwise they are filed from `outs` (fileLoads) at a
// break and before anything else reads them: a run's end, a restart file,
// an output of the bonds (sweep.rs in the core). Filing also settles the
// rest of a broken bond's record (its contact), so a row needs neither the
// contact nor the loads.
#ifndef GRANBOND_BOND_INDEX_H
#define GRANBOND_BOND_INDEX_H

#include "granbond.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_set>
#include <vector>

namespace granbond {

// The engine's per-pair flag of an indexed bond, where the adapter owns the
// contact loop (LAMMPS): the loop leaves the pair to the sweep without
// reading its record. Engines treat any non-zero flag as "keep the record"
// (partners), so the mark survives their bookkeeping. Where the engine owns
// the loop (LIGGGHTS), its callbacks read the bond's status instead, and the
// flags are the engine's own.
const int kSweptMark = 2;
// The flag of a pair whose bond broke in this pass's sweep (LAMMPS): the
// contact loop treats it as a contact, and no bond forms on it before the
// next pass, as when the bond is stepped in its pair's turn.
const int kBrokeMark = 3;

struct BondIndex {
    const GbBondModel *model = nullptr;
    GbSweepPass pass{};
    std::vector<int32_t> pairs;      // i, j per bond
    std::vector<uint8_t> counted;    // this rank counts the bond (each bond on one rank)
    std::vector<double *> records;   // what the core steps: the homes, or their rows
    std::vector<double *> homes;     // each bond's record in the engine's pages
    std::vector<int *> flags;        // the engine's flag of each bond's pair
    std::vector<GbBondOutput> outs;  // each bond's latest pass (status 0: none since indexed)
    // The bonds that broke in the sweeps since the last keepIntact: their
    // positions, ascending within a sweep, and their outputs (mode,
    // stresses).
    std::vector<size_t> broken;
    std::vector<GbBondOutput> brokenOut;
    // The first `ordered` bonds are in the order of the engine's lists (as
    // indexed when they were built); those after them formed since.
    size_t ordered = 0;

    size_t size() const { return records.size(); }
    // Memory held: the rows and, per bond, the pair, the flags and pointers.
    double bytes() const
    {
        const size_t perBond =
            2 * sizeof(int32_t) + sizeof(uint8_t) + 2 * sizeof(double *) + sizeof(int *) + sizeof(GbBondOutput);
        return static_cast<double>(rows_.capacity() * sizeof(double) + records.capacity() * perBond);
    }
    // From now on the bonds' states are stepped in rows (see the head of
    // this file); `layout` is that of the homes; the index must be empty.
    void useRows(const GbRecordLayout &layout)
    {
        rowLen_ = layout.loads - layout.bond;
        contactLen_ = layout.bond;
    }
    // ... or in their homes (the default); the index must be empty.
    void useHomes() { rowLen_ = contactLen_ = 0; }
    bool usesRows() const { return rowLen_ != 0; }
    // Bond k's status, from what the core steps (`status`: its place in a
    // home).
    double statusOf(size_t k, size_t status) const { return records[k][rowLen_ ? status - contactLen_ : status]; }
    void clear()
    {
        pairs.clear();
        counted.clear();
        records.clear();
        homes.clear();
        flags.clear();
        outs.clear();
        broken.clear();
        brokenOut.clear();
        rows_.clear();
        ordered = 0;
    }
    void add(int i, int j, bool counts, double *record, int *flag)
    {
        pairs.push_back(i);
        pairs.push_back(j);
        counted.push_back(counts ? 1 : 0);
        homes.push_back(record);
        flags.push_back(flag);
        outs.push_back(GbBondOutput());
        if (!rowLen_) {
            records.push_back(record);
            return;
        }
        if (rows_.size() + rowLen_ > rows_.capacity()) {
            rows_.reserve(std::max(2 * rows_.capacity(), kFirstRows * rowLen_));
            for (size_t k = 0; k < records.size(); k++) records[k] = rows_.data() + k * rowLen_;
        }
        records.push_back(rows_.data() + rows_.size());
        rows_.insert(rows_.end(), record + contactLen_, record + contactLen_ + rowLen_);
    }
    // Every bond's row written back to its home, and its loads filed there
    // (before the engine reads or moves its records).
    GbStatus writeBack()
    {
        if (rowLen_)
            for (size_t k = 0; k < size(); k++) copyRow(k);
        return fileLoads(0, size());
    }
    // The loads of the bonds from `first` to `last` filed in their homes.
    GbStatus fileLoads(size_t first, size_t last)
    {
        if (first >= last) return GB_STATUS_OK;
        size_t failed = 0;
        return granbond_bond_file_loads(&pass, last - first, homes.data() + first, outs.data() + first, &failed);
    }
    // Bond k's whole record as a pass that keeps the loads would leave it,
    // in `scratch`, for outputs of the bonds; `layout` is that of the homes
    // (granbond_record_layout of `pass.with_contact`).
    const double *wholeRecord(size_t k, const GbRecordLayout &layout, std::vector<double> &scratch,
                              GbStatus &status) const
    {
        scratch.assign(homes[k], homes[k] + layout.len);
        if (rowLen_) std::copy(records[k], records[k] + rowLen_, scratch.begin() + contactLen_);
        double *whole = scratch.data();
        size_t failed = 0;
        status = granbond_bond_file_loads(&pass, 1, &whole, &outs[k], &failed);
        return whole;
    }

    // Core calls over the bonds from `first` to `last` (`advance`: a force pass),
    // reading the atoms of `atom` (x, v, omega: blocks of 3 doubles per
    // atom; local and ghost atoms). `intact(k, out)` is called for each bond
    // that held, in index order; those that broke are added to `broken`.
    // The core is called for a few hundred bonds at a time, so that their
    // outputs are still in cache when `intact` reads them. On failure `bad`
    // is the bond's position in the index.
    template<class Atom, class Intact>
    GbStatus sweep(const Atom *atom, size_t first, size_t last, bool advance, double dt, GbSweepTally &tally,
                   size_t &bad, Intact intact)
    {
        GbAtomArrays arrays;
        arrays.x = atom->x[0];
        arrays.v = atom->v[0];
        arrays.omega = atom->omega[0];
        arrays.radius = atom->radius;
        arrays.count = static_cast<size_t>(atom->nlocal + atom->nghost);
        pass.advance = advance ? 1 : 0;
        pass.dt = dt;
        GbRecordLayout layout;
        const GbStatus laid = granbond_record_layout(pass.with_contact, &layout);
        if (laid != GB_STATUS_OK) return laid;
        // a force pass steps the rows, bond states alone; a setup pass reads
        // the loads filed in the homes
        double *const *stepped = (rowLen_ && !advance) ? homes.data() : records.data();
        GbSweepPass stepping = pass;
        if (rowLen_ && advance) stepping.with_contact = 0;
        for (size_t from = first; from < last; from += kSweepChunk) {
            const size_t n = last - from < kSweepChunk ? last - from : kSweepChunk;
            // the core requests each call's records ahead from its second
            // block on; the first block of the next call is requested here
            // (rows stream in order by themselves)
            for (size_t k = from + n; !rowLen_ && k < last && k < from + n + kAhead; k++)
                for (size_t s = 0; s < layout.len; s += 8) __builtin_prefetch(records[k] + s, 1);
            size_t failed = 0;
            GbBondOutput *const out = outs.data() + from;
            const GbStatus status = granbond_bond_sweep(model, &stepping, n, &arrays, pairs.data() + 2 * from,
                                                        counted.data() + from, stepped + from, out, &tally,
                                                        &failed);
            if (status != GB_STATUS_OK) {
                bad = from + (failed < n ? failed : 0);
                return status;
            }
            for (size_t c = 0; c < n; c++) {
                if (out[c].status == GB_BOND_STATUS_INTACT) {
                    intact(from + c, out[c]);
                    continue;
                }
                broken.push_back(from + c);
                brokenOut.push_back(out[c]);
                // the engine's loop reads it now
                if (rowLen_) copyRow(from + c);
                if (rowLen_ || !pass.keep_loads) {
                    const GbStatus filed = fileLoads(from + c, from + c + 1);
                    if (filed != GB_STATUS_OK) {
                        bad = from + c;
                        return filed;
                    }
                }
            }
        }
        return GB_STATUS_OK;
    }

    // Drops the bonds that broke in the latest sweeps, keeping the order of
    // the rest.
    void keepIntact()
    {
        if (broken.empty()) return;   // the common case: all held
        // a pass may sweep a bond formed in it (at the end) before others
        std::sort(broken.begin(), broken.end());
        ordered -= static_cast<size_t>(std::lower_bound(broken.begin(), broken.end(), ordered) - broken.begin());
        size_t kept = broken[0], next = 0;
        for (size_t k = kept; k < size(); k++) {
            if (next < broken.size() && broken[next] == k) {
                next++;
                continue;
            }
            pairs[2 * kept] = pairs[2 * k];
            pairs[2 * kept + 1] = pairs[2 * k + 1];
            counted[kept] = counted[k];
            homes[kept] = homes[k];
            flags[kept] = flags[k];
            outs[kept] = outs[k];
            if (rowLen_)
                std::copy(records[k], records[k] + rowLen_, records[kept]);
            else
                records[kept] = records[k];
            kept++;
        }
        pairs.resize(2 * kept);
        counted.resize(kept);
        records.resize(kept);
        homes.resize(kept);
        flags.resize(kept);
        outs.resize(kept);
        rows_.resize(kept * rowLen_);
        broken.clear();
        brokenOut.clear();
    }

private:
    // Row k's bond state back to its home. The home's contact state is the
    // contact loop's to step where the contact goes on under the bond;
    // otherwise nothing writes it while the bond holds, and filing clears it
    // at a break.
    void copyRow(size_t k) { std::copy(records[k], records[k] + rowLen_, homes[k] + contactLen_); }

    std::vector<double> rows_;
    size_t rowLen_ = 0;       // 0: the core steps the homes; else the bond state's length
    size_t contactLen_ = 0;
    static const size_t kFirstRows = 256;
    static const size_t kSweepChunk = 512;
    static const size_t kAhead = 64;   // the core's own block of bonds (ffi/sweep.rs)
};

// The index of `model` in `indices`, made on first use.
inline BondIndex &indexOf(std::vector<BondIndex> &indices, const GbBondModel *model)
{
    for (BondIndex &b : indices)
        if (b.model == model) return b;
    indices.push_back(BondIndex());
    indices.back().model = model;
    return indices.back();
}

// The check of an index against the records it was built from: every
// record whose status is intact (`status` doubles from its start) is in the
// index once (`marked`: with its flag kSweptMark), and nothing else is.
// `visit(f)` calls `f(record, flag)` for every pair of the engine's lists
// whose type pair bonds. Returns what is wrong, or an empty string.
template<class Visit>
std::string checkIndex(const std::vector<BondIndex> &indices, size_t status, bool marked, Visit visit)
{
    std::unordered_set<const double *> indexed;
    size_t entries = 0;
    for (const BondIndex &b : indices)
        for (size_t k = 0; k < b.size(); k++) {
            entries++;
            if (!indexed.insert(b.homes[k]).second) return "a bond is in the index twice";
            if (b.statusOf(k, status) != GB_BOND_STATUS_INTACT || b.homes[k][status] != GB_BOND_STATUS_INTACT)
                return "the index holds a bond that is not intact";
            if (marked && *b.flags[k] != kSweptMark) return "an indexed bond's pair is not marked";
        }
    size_t intact = 0;
    std::string wrong;
    visit([&](const double *record, const int *flag) {
        if (record[status] != GB_BOND_STATUS_INTACT) {
            if (marked && *flag == kSweptMark && wrong.empty())
                wrong = "a pair is marked as an indexed bond but is not intact";
            return;
        }
        intact++;
        if (!indexed.count(record) && wrong.empty()) wrong = "an intact bond is missing from the index";
    });
    if (!wrong.empty()) return wrong;
    if (intact != entries)
        return "the records hold " + std::to_string(intact) + " intact bonds, the index " + std::to_string(entries);
    return std::string();
}

}

#endif
