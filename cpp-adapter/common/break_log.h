// The log of broken bonds, the same in both engines' `fix bond/breaklog`
// (docs/reference/fix_bond_breaklog.md). The core makes each event, reads
// the fix's words and writes the lines (granbond_break_event,
// granbond_break_log_words, granbond_break_log_text); the adapters fill
// one event per bond that broke on the rank that counts it (each bond
// once over all ranks), and rank 0 gathers them and writes the file.
#ifndef GRANBOND_BREAK_LOG_H
#define GRANBOND_BREAK_LOG_H

#include "core_message.h"
#include "granbond.h"

#include <mpi.h>

#include <cstdio>
#include <string>
#include <vector>

namespace granbond {

typedef GbBreakEvent BreakEvent;

// The event of the bond between atoms i and j of an engine's `atom` that
// broke with `out`, at `step`. On failure the core's message says why.
template<class Atom>
GbStatus makeBreakEvent(const GbBondModel *model, const GbBondOutput &out, const Atom *atom, int i, int j,
                        double step, BreakEvent &e)
{
    return granbond_break_event(model, &out, atom->x[i], atom->x[j], atom->radius[i], atom->radius[j],
                                static_cast<double>(atom->tag[i]), static_cast<double>(atom->tag[j]), step, &e);
}

// The core's lines for `events` (the header first where `header`).
inline std::string breakLogText(std::vector<BreakEvent> &events, bool header)
{
    std::vector<char> text((events.size() + 1) * GRANBOND_BREAK_LOG_LINE_LEN);
    if (granbond_break_log_text(events.data(), events.size(), header ? 1 : 0, text.data(), text.size()) !=
        GB_STATUS_OK)
        return "# the break log's lines: " + coreReason() + "\n";
    return text.data();
}

// Gathers every rank's `mine` on rank 0 (and clears it), which writes them
// to `file`. Collective.
inline void writeBreakEvents(std::vector<BreakEvent> &mine, FILE *file, MPI_Comm world)
{
    int me = 0, nprocs = 1;
    MPI_Comm_rank(world, &me);
    MPI_Comm_size(world, &nprocs);
    const int fields = sizeof(BreakEvent) / sizeof(double);
    int count = static_cast<int>(mine.size()) * fields;
    std::vector<int> counts(nprocs), offsets(nprocs);
    MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, world);
    int total = 0;
    if (me == 0)
        for (int p = 0; p < nprocs; p++) {
            offsets[p] = total;
            total += counts[p];
        }
    std::vector<BreakEvent> all(me == 0 ? total / fields : 0);
    MPI_Gatherv(reinterpret_cast<double *>(mine.data()), count, MPI_DOUBLE, reinterpret_cast<double *>(all.data()),
                counts.data(), offsets.data(), MPI_DOUBLE, 0, world);
    mine.clear();
    if (me != 0 || all.empty() || !file) return;
    std::fputs(breakLogText(all, false).c_str(), file);
    std::fflush(file);
}

// The words of `fix ID group bond/breaklog FILE [every N]` and the file
// they name, the same in both engines' fix: rank 0 opens the file and
// writes the header, and every rank's events go to it.
class BreakLogFile {
public:
    BreakLogFile() = default;
    BreakLogFile(const BreakLogFile &) = delete;
    BreakLogFile &operator=(const BreakLogFile &) = delete;
    ~BreakLogFile()
    {
        if (file_) std::fclose(file_);
    }

    // Reads the fix's words (all of them, its id first); `every`: how many
    // steps apart the log is written. Returns what is wrong, naming the
    // word, or an empty string.
    static std::string words(int narg, char **arg, int &every)
    {
        int32_t n = 0;
        if (granbond_break_log_words(arg, static_cast<size_t>(narg), &n) != GB_STATUS_OK) return coreReason();
        every = n;
        return std::string();
    }

    // Opens `path` and writes the header on rank `me` 0; returns what went
    // wrong on this rank, or an empty string.
    std::string open(const char *path, int me)
    {
        if (me != 0) return std::string();
        file_ = std::fopen(path, "w");
        if (!file_) return std::string("cannot open ") + path;
        std::vector<BreakEvent> none;
        std::fputs(breakLogText(none, true).c_str(), file_);
        std::fflush(file_);
        return std::string();
    }

    // Gathers every rank's `mine` (and clears it) and writes them. Collective.
    void write(std::vector<BreakEvent> &mine, MPI_Comm world) { writeBreakEvents(mine, file_, world); }

private:
    FILE *file_ = nullptr;
};

}

#endif
