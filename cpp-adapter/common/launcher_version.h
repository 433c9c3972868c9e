// `--version` of the launchers: granbond's version, the C ABI version of the
// core linked into the adapter, and the engine's version. The engine sets
// its version string in its constructor, so the launcher builds an instance
// that writes nothing (QuietArgs) and reads it.
#ifndef GRANBOND_LAUNCHER_VERSION_H
#define GRANBOND_LAUNCHER_VERSION_H

#include <mpi.h>
#include <cstdio>
#include <cstring>

namespace granbond {

inline bool askedForVersion(int argc, char **argv)
{
    for (int i = 1; i < argc; i++)
        if (std::strcmp(argv[i], "--version") == 0) return true;
    return false;
}

// Command line of an engine instance with no screen or log output.
struct QuietArgs {
    explicit QuietArgs(const char *program)
    {
        std::snprintf(program_, sizeof program_, "%s", program);
        argv[0] = program_;
        argv[1] = screen_;
        argv[2] = none1_;
        argv[3] = log_;
        argv[4] = none2_;
        argv[5] = nullptr;
    }
    int argc = 5;
    char *argv[6];

private:
    char program_[64];
    char screen_[8] = "-screen", log_[8] = "-log", none1_[8] = "none", none2_[8] = "none";
};

// `engine` names the engine and its version, as the engine words it.
inline void printVersions(const char *engine, unsigned abiVersion)
{
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (rank != 0) return;
    std::printf("granbond %s\n", GRANBOND_VERSION);
    std::printf("granbond core ABI %u\n", abiVersion);
    std::printf("engine %s\n", engine);
}

}

#endif
