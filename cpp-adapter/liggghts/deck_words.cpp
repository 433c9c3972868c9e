#include "deck_words.h"
#include "core_bridge.h"
#include "granbond.h"

#include "fix_property_global.h"
#include "modify.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace granbond {
namespace liggghts {

namespace {

bool isSwitchValue(const char *w)
{
    return !std::strcmp(w, "on") || !std::strcmp(w, "off") || !std::strcmp(w, "yes") || !std::strcmp(w, "no");
}

// A granbond property of LIGGGHTS decks: its name, whether it is a
// per-type-pair matrix (else a scalar) and whether `inf` is one of its
// values, from the core's tables.
struct PropertyRow {
    std::string name;
    bool perTypePair;
    bool infinite;
};

template<class Info>
void addRows(std::vector<PropertyRow> &rows, size_t count, Info info)
{
    for (size_t id = 0; id < count; id++) {
        GbParameterInfo row;
        if (info(id, &row) != GB_STATUS_OK) continue;
        const bool perTypePair = row.liggghts_source == GB_LIGGGHTS_SOURCE_PER_TYPE_PAIR ||
                                 row.liggghts_source == GB_LIGGGHTS_SOURCE_OPTIONAL_PER_TYPE_PAIR;
        if (!perTypePair && row.liggghts_source != GB_LIGGGHTS_SOURCE_SCALAR) continue;
        rows.push_back({row.liggghts_name, perTypePair, std::strstr(row.range, "inf") != nullptr});
    }
}

const PropertyRow *propertyRow(const char *name)
{
    static std::vector<PropertyRow> rows;
    if (rows.empty()) {
        addRows(rows, granbond_bond_parameter_count(), &granbond_bond_parameter_info);
        addRows(rows, granbond_voigt_parameter_count(), &granbond_voigt_parameter_info);
    }
    for (const PropertyRow &r : rows)
        if (r.name == name) return &r;
    return nullptr;
}

StyleCreator &engineCreator()
{
    static StyleCreator creator = nullptr;
    return creator;
}

// The spelling of infinity the engine's number reader takes (it refuses
// "inf"; "1e999" passes its character check and reads as infinity).
char kInfinity[] = "1e999";

// The atom types of the k-th value of an N x N matrix, for messages.
std::string typesOf(int k, long n, bool perTypePair)
{
    if (!perTypePair) return "";
    return " (atom types " + std::to_string(k / n + 1) + " and " + std::to_string(k % n + 1) + ")";
}

LAMMPS_NS::Fix *checkedPropertyGlobal(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg)
{
    const PropertyRow *row = narg > 3 ? propertyRow(arg[3]) : nullptr;
    if (row) {
        const std::string command = std::string("fix ") + arg[0] + " property/global " + row->name;
        const char *need = row->perTypePair ? "peratomtypepair N followed by N*N values" : "scalar VALUE";
        if (narg < 5)
            endRun(lmp->error, FLERR, command + ": no style and values; write " + row->name + " " + need);
        const bool pairStyle = !std::strcmp(arg[4], "peratomtypepair") || !std::strcmp(arg[4], "atomtypepair");
        if (row->perTypePair ? !pairStyle : std::strcmp(arg[4], "scalar") != 0)
            endRun(lmp->error, FLERR, command + ": given as '" + arg[4] + "'; granbond reads " + row->name +
                                          " only as " + need);
        int first = 5;
        long n = 1;
        if (row->perTypePair) {
            char *end = nullptr;
            n = narg > 5 ? std::strtol(arg[5], &end, 10) : 0;
            if (narg <= 5 || *end != '\0' || n < 1 || n > 32767)
                endRun(lmp->error, FLERR, command + ": peratomtypepair needs the number of atom types N (an "
                                              "integer >= 1), got '" + (narg > 5 ? arg[5] : "") + "'");
            first = 6;
        }
        // the engine's own options between N and the values are its to read
        while (first + 1 < narg && (!std::strcmp(arg[first], "type") || !std::strcmp(arg[first], "warn_out_of_bounds")))
            first += 2;
        const long want = n * n;
        if (narg - first != want)
            endRun(lmp->error, FLERR, command + ": " + (row->perTypePair ? "peratomtypepair " + std::to_string(n) +
                                                                              " needs " + std::to_string(want) + " values"
                                                                        : std::string("scalar needs one value")) +
                                          ", got " + std::to_string(narg - first));
        for (int k = first; k < narg; k++) {
            const std::string word = arg[k];
            const std::string where = typesOf(k - first, n, row->perTypePair);
            char *end = nullptr;
            const double v = std::strtod(arg[k], &end);
            const bool parsed = end != arg[k] && *end == '\0';
            if (parsed && std::isinf(v)) {
                if (!row->infinite || v < 0.0)
                    endRun(lmp->error, FLERR, command + where + ": '" + word + "' is not a finite number");
                arg[k] = kInfinity;
                continue;
            }
            // a number, in the characters the engine's number reader takes
            if (!parsed || word.find_first_not_of("0123456789+-.eE") != std::string::npos)
                endRun(lmp->error, FLERR, command + where + ": '" + word + "' is not a number");
        }
        // a second line for the same property: the engine would refuse it
        // without naming the property, or keep one of the two silently
        for (int i = 0; i < lmp->modify->nfix; i++) {
            LAMMPS_NS::FixPropertyGlobal *f = dynamic_cast<LAMMPS_NS::FixPropertyGlobal *>(lmp->modify->fix[i]);
            if (f && std::strcmp(f->id, arg[0]) != 0 &&
                f->check_fix(row->name.c_str(), row->perTypePair ? "peratomtypepair" : "scalar", 0, 0, "granbond", false))
                endRun(lmp->error, FLERR, command + ": " + row->name + " is already defined by fix " + f->id +
                                              "; define each property once (unfix " + f->id +
                                              " first to replace it)");
        }
    }
    return engineCreator()(lmp, narg, arg);
}

}

void checkSettingsWords(LAMMPS_NS::LAMMPS *lmp, const std::string &command, int nargs, char **args)
{
    std::map<std::string, std::string> given;
    for (int i = 0; i < nargs; i += 2) {
        if (i + 1 >= nargs)
            endRun(lmp->error, FLERR, command + ": '" + args[i] + "' has no value at the end of the line (a " +
                                          "switch takes on or off: " + args[i] + " on)");
        // a value that is not a switch's: the engine's parser refuses it,
        // naming the setting, before it reaches the end of the line
        if (!isSwitchValue(args[i + 1])) return;
        const auto seen = given.find(args[i]);
        if (seen != given.end() && seen->second != args[i + 1])
            endRun(lmp->error, FLERR, command + ": switch " + args[i] + " is given twice, " + seen->second +
                                          " and then " + args[i + 1] + "; give it once");
        given[args[i]] = args[i + 1];
    }
}

void checkPropertyLines(std::map<std::string, StyleCreator> &fixes)
{
    StyleCreator &slot = fixes["property/global"];
    if (slot == &checkedPropertyGlobal || !slot) return;
    engineCreator() = slot;
    slot = &checkedPropertyGlobal;
}

}
}
