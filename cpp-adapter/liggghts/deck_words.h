// The deck's granbond words checked before the engine's parsers read them,
// so that a bad one ends the run with a message naming it: the switches of
// `pair_style gran` and `fix wall/gran` (the engine's settings parser reads
// past the end of the line after a switch without a value, and lets a
// repeated switch win silently), and the values of granbond's
// `fix property/global` lines (the engine's reader names no property). The
// core checks the words (granbond_liggghts_settings_check,
// granbond_liggghts_property_line_check); this hooks the checks in.
#ifndef GRANBOND_LIGGGHTS_DECK_WORDS_H
#define GRANBOND_LIGGGHTS_DECK_WORDS_H

#include "liggghts_engine.h"

#include <map>
#include <string>

namespace granbond {
namespace liggghts {

// Ends the run if the settings words of `command` hold a word without a
// value at the end, or a switch given twice with different values. Every
// setting of the engine's parser is a name and one value, so a name left
// alone at the end can never parse.
void checkSettingsWords(LAMMPS_NS::LAMMPS *lmp, const std::string &command, int nargs, char **args);

typedef LAMMPS_NS::Fix *(*StyleCreator)(LAMMPS_NS::LAMMPS *, int, char **);

// Puts the check of granbond's `fix property/global` lines in front of the
// engine's creator in `fixes` (the style table of one LAMMPS instance).
void checkPropertyLines(std::map<std::string, StyleCreator> &fixes);

}
}

#endif
