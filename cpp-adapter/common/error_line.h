// The line a run ends with on one rank, written and flushed to the screen
// and the log first: error->one aborts MPI without flushing them, so a
// redirected screen or log would lose the message. Both engines' adapters
// call it before error->one.
#ifndef GRANBOND_ERROR_LINE_H
#define GRANBOND_ERROR_LINE_H

#include "comm.h"
#include "lammps.h"

#include <cstdio>
#include <string>

namespace granbond {

inline void flushErrorLine(LAMMPS_NS::LAMMPS *lmp, const std::string &text)
{
    FILE *streams[2] = {lmp->screen, lmp->logfile};
    for (FILE *s : streams)
        if (s) {
            std::fprintf(s, "ERROR on proc %d: %s\n", lmp->comm->me, text.c_str());
            std::fflush(s);
        }
}

}

#endif
