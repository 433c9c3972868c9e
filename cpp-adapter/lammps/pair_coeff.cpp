// pair_style granbond's `pair_style` and `pair_coeff` commands: the words of
// a type pair's models translated to rows of the core's parameter tables,
// and the core's models built from them.
//
//   pair_coeff I J voigt <values> [voigt keyword ...] [bond/nonlinear keyword ...]
//
// A keyword is a row of the model's table (its value written as the row's
// kind says) or one of the model's phrases: opening words, values for the
// rows the phrase names, and rows the phrase sets itself (granbond.h,
// granbond_*_phrase_info). The grammar's rules are the core's phrases; this
// file only looks words up.
#include "pair_granbond.h"
#include "core_message.h"

#include "atom.h"
#include "error.h"
#include "utils.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

using namespace LAMMPS_NS;

namespace granbond {
namespace lammps {

namespace {

// The model words of pair_coeff; `contact_under_bond` is the pass's own
// setting (whether the contact is stepped under an intact bond), given in
// the bond's clause.
const char *const kVoigt = "voigt";
const char *const kBond = "bond/nonlinear";
const char *const kContactUnderBond = "contact_under_bond";

std::vector<std::string> split(const char *s)
{
    std::istringstream in(s);
    std::vector<std::string> words;
    for (std::string w; in >> w;) words.push_back(w);
    return words;
}

// The words of one pair_coeff command; errors name the command as the deck
// wrote it and the clause being read.
class Args {
public:
    Args(int narg, char **arg, Error *error) :
        narg_(narg), arg_(arg), error_(error), at_(2), command_(std::string("pair_coeff ") + arg[0] + " " + arg[1])
    {}
    bool done() const { return at_ >= narg_; }
    std::string peek(int ahead = 0) const
    {
        return at_ + ahead < narg_ ? std::string(arg_[at_ + ahead]) : std::string();
    }
    std::string word(const std::string &what)
    {
        if (done()) fail("missing " + what);
        return arg_[at_++];
    }
    void skip(int n) { at_ += n; }
    void clause(const std::string &name) { clause_ = name; }
    [[noreturn]] void fail(const std::string &what)
    {
        error_->all(FLERR, command_ + (clause_.empty() ? "" : " " + clause_) + ": " + what);
        std::abort();   // not reached
    }

private:
    int narg_;
    char **arg_;
    Error *error_;
    int at_;
    std::string command_, clause_;
};

bool isNumber(const std::string &s)
{
    if (s.empty()) return false;
    char *end = nullptr;
    std::strtod(s.c_str(), &end);
    return end != s.c_str() && *end == '\0';
}

// A deck's value for a row of `kind`, as the core takes it (switches 1 or 0,
// steps as exact doubles).
double value(Args &a, GbParameterKind kind, const std::string &what)
{
    const std::string s = a.word(what);
    errno = 0;
    char *end = nullptr;
    if (kind == GB_PARAMETER_KIND_SWITCH) {
        if (s == "yes" || s == "on") return 1.0;
        if (s == "no" || s == "off") return 0.0;
        a.fail(what + " expects yes|no (or on|off), got '" + s + "'");
    }
    if (kind == GB_PARAMETER_KIND_INTEGER) {
        const long long v = std::strtoll(s.c_str(), &end, 10);
        if (end == s.c_str() || *end != '\0' || errno == ERANGE) a.fail(what + " expects an integer, got '" + s + "'");
        return static_cast<double>(v);
    }
    const double v = std::strtod(s.c_str(), &end);
    if (end == s.c_str() || *end != '\0' || errno == ERANGE) a.fail(what + " expects a number, got '" + s + "'");
    return v;
}

// One model's clause of pair_coeff, read into `P` through the core's table
// and phrases.
template<class P>
class Clause {
public:
    using Info = GbStatus (*)(size_t, GbParameterInfo *);
    using PhraseInfo = GbStatus (*)(size_t, GbPhrase *);
    using Set = GbStatus (*)(P *, const char *, double);

    Clause(Args &a, const char *model, Info info, PhraseInfo phrase, Set set, P &params) :
        a_(a), model_(model), set_(set), params_(params)
    {
        GbParameterInfo row;
        for (size_t id = 0; info(id, &row) == GB_STATUS_OK; id++) rows_.push_back(row);
        GbPhrase p;
        for (size_t id = 0; phrase(id, &p) == GB_STATUS_OK; id++) phrases_.push_back(p);
        givenBy_.assign(rows_.size(), std::string());
        givenValue_.assign(rows_.size(), 0.0);
        a_.clause(model_);
    }

    // The values that follow the model's name.
    void head()
    {
        for (const GbPhrase &p : phrases_) {
            if (*p.words) continue;
            // too few numbers: name the values the model expects, not the
            // word that stood where the last one should
            const std::vector<std::string> reads = split(p.reads);
            size_t k = 0;
            while (k < reads.size() && isNumber(a_.peek(static_cast<int>(k)))) k++;
            if (k < reads.size() && (a_.peek(static_cast<int>(k)).empty() || !isNumber(a_.peek(static_cast<int>(k)))))
                a_.fail(std::string(model_) + " expects " + std::to_string(reads.size()) + " numbers (" + p.reads +
                        "), got " + std::to_string(k) +
                        (a_.peek(static_cast<int>(k)).empty() ? std::string() : " before '" + a_.peek(static_cast<int>(k)) + "'"));
            read(p, "");
        }
    }

    // Reads the phrase or keyword at the next word; false when the word is
    // neither (the caller's word, or an unknown one).
    bool next()
    {
        const std::string w = a_.peek();
        const GbPhrase *best = nullptr;
        size_t bestLen = 0;
        for (const GbPhrase &p : phrases_) {
            const std::vector<std::string> words = split(p.words);
            if (words.empty() || (*p.follows && last_ != p.follows)) continue;
            size_t k = 0;
            while (k < words.size() && a_.peek(static_cast<int>(k)) == words[k]) k++;
            if (k == words.size() && k > bestLen) {
                best = &p;
                bestLen = k;
            }
        }
        if (best) {
            a_.skip(static_cast<int>(bestLen));
            read(*best, best->words);
            last_ = best->words;
            return true;
        }
        last_.clear();
        if (const GbParameterInfo *row = find(w)) {
            a_.skip(1);
            const double v = value(a_, row->kind, w);
            store(row->keyword, v, a_.peek(-1), w + " " + a_.peek(-1));
            return true;
        }
        // the opening word of phrases whose next word is wrong
        std::string choices;
        for (const GbPhrase &p : phrases_) {
            const std::vector<std::string> words = split(p.words);
            if (words.size() > 1 && words[0] == w) choices += (choices.empty() ? "" : " or ") + words[1];
        }
        if (!choices.empty()) {
            a_.skip(1);
            const std::string got = a_.word(w + " " + choices);
            a_.fail(w + " expects " + choices + ", got '" + got + "'");
        }
        return false;
    }

    // Every word this clause knows, for the message of an unknown one.
    std::string known() const
    {
        std::vector<std::string> words;
        for (const GbPhrase &p : phrases_) {
            const std::vector<std::string> w = split(p.words);
            if (!w.empty() && !*p.follows && std::find(words.begin(), words.end(), w[0]) == words.end()) words.push_back(w[0]);
        }
        for (const GbParameterInfo &r : rows_)
            if (std::find(words.begin(), words.end(), r.keyword) == words.end()) words.push_back(r.keyword);
        std::string s;
        for (const std::string &w : words) s += (s.empty() ? "" : " ") + w;
        return s;
    }

private:
    const GbParameterInfo *find(const std::string &keyword) const
    {
        for (const GbParameterInfo &r : rows_)
            if (keyword == r.keyword) return &r;
        return nullptr;
    }

    // A phrase's values, then what the phrase sets itself.
    void read(const GbPhrase &p, const std::string &name)
    {
        const std::vector<std::string> reads = split(p.reads);
        for (const std::string &keyword : reads) {
            const GbParameterInfo *row = find(keyword);
            if (!row) a_.fail("the core's phrase '" + name + "' reads '" + keyword + "', which its table lacks");
            const std::string what = name.empty() ? keyword : reads.size() == 1 ? name : name + " " + keyword;
            const double v = value(a_, row->kind, what);
            store(row->keyword, v, a_.peek(-1), name.empty() ? std::string(model_) : name);
        }
        // what the values after the model's name imply is a default that a
        // later phrase may change (`rolling` after `voigt`)
        const std::vector<std::string> sets = split(p.sets);
        for (size_t k = 0; k + 1 < sets.size(); k += 2)
            store(sets[k].c_str(), std::strtod(sets[k + 1].c_str(), nullptr), sets[k + 1], name);
    }

    // The core refuses a value out of range; the message names the keyword
    // and the value as the deck wrote it. A row given twice on the line with
    // different values is refused, naming both (`origin`: the words that
    // gave it; empty for a default the values after the model's name imply).
    void store(const char *keyword, double v, const std::string &written, const std::string &origin)
    {
        const GbParameterInfo *row = find(keyword);
        const size_t id = row ? static_cast<size_t>(row - rows_.data()) : rows_.size();
        if (id < rows_.size() && !origin.empty()) {
            if (!givenBy_[id].empty() && givenValue_[id] != v)
                a_.fail("'" + origin + "' conflicts with '" + givenBy_[id] + "' given before on this line (" + keyword +
                        " set twice to different values); give each keyword once");
            givenBy_[id] = origin;
            givenValue_[id] = v;
        }
        if (set_(&params_, keyword, v) == GB_STATUS_OK) return;
        if (granbond_last_error_parameter() >= 0 && static_cast<size_t>(granbond_last_error_parameter()) < rows_.size()) {
            // the core's requirement (the row's range, or more), with the
            // value as the deck wrote it
            const std::string reason = coreReason();
            const size_t from = reason.find(" must be "), to = reason.rfind("; got ");
            const std::string need = from != std::string::npos && to != std::string::npos && to > from
                                         ? reason.substr(from + 9, to - from - 9)
                                         : std::string(rows_[granbond_last_error_parameter()].range);
            a_.fail(std::string(keyword) + " must be " + need + ", got " + written);
        }
        a_.fail(coreReason());
    }

    Args &a_;
    const char *model_;
    Set set_;
    P &params_;
    std::vector<GbParameterInfo> rows_;
    std::vector<GbPhrase> phrases_;
    std::string last_;   // the phrase just read, for one that may only follow it
    std::vector<std::string> givenBy_;   // per row: the words that gave it on this line
    std::vector<double> givenValue_;     // ... and the value they gave
};

}

// pair_style granbond [energy yes|no]: the models are per type pair; the
// one setting is whether the bonds' energy budget is kept (compute pair
// granbond's values 9-11).
void PairGranbond::settings(int narg, char **arg)
{
    const bool energy = narg == 2 && std::strcmp(arg[0], "energy") == 0;
    if (narg != 0 && !energy)
        error->all(FLERR, std::string("pair_style granbond takes only 'energy yes|no' (got '") + arg[0] +
                              "'); the models are set per type pair with pair_coeff");
    if (narg == 0) {
        energyBudget = false;
        return;
    }
    const std::string value = arg[1];
    if (value != "yes" && value != "on" && value != "no" && value != "off")
        error->all(FLERR, "pair_style granbond energy: expected yes or no (or on, off), got '" + value + "'");
    energyBudget = value == "yes" || value == "on";
}

void PairGranbond::coeff(int narg, char **arg)
{
    if (!allocated) allocate();
    if (narg < 3) error->all(FLERR, "pair_coeff: pair_style granbond expects I J voigt ... [bond/nonlinear ...]");
    int ilo, ihi, jlo, jhi;
    utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
    utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);

    Args a(narg, arg, error);
    TypePair tp;
    std::memset(&tp, 0, sizeof tp);
    granbond_voigt_params_default(&tp.voigt);
    granbond_bond_params_default(&tp.bond);
    tp.hasBond = 0;

    const std::string model = a.word("model (" + std::string(kVoigt) + ")");
    if (model != kVoigt) a.fail("unknown model '" + model + "' (expected " + kVoigt + ")");
    Clause<GbVoigtParams> voigt(a, kVoigt, &granbond_voigt_parameter_info, &granbond_voigt_phrase_info,
                                &granbond_voigt_params_set, tp.voigt);
    voigt.head();
    while (!a.done() && a.peek() != kBond)
        if (!voigt.next())
            a.fail("unknown keyword '" + a.peek() + "' (known: " + voigt.known() + ", then " + kBond + ")");
    if (!a.done()) {
        a.word(kBond);
        tp.hasBond = 1;
        Clause<GbBondParams> bond(a, kBond, &granbond_bond_parameter_info, &granbond_bond_phrase_info,
                                  &granbond_bond_params_set, tp.bond);
        bool underBondGiven = false;
        while (!a.done()) {
            if (a.peek() == kContactUnderBond) {
                a.skip(1);
                const int32_t v = static_cast<int32_t>(value(a, GB_PARAMETER_KIND_SWITCH, kContactUnderBond));
                if (underBondGiven && v != tp.contactUnderBond)
                    a.fail(std::string(kContactUnderBond) + " is given twice with different values; give it once");
                underBondGiven = true;
                tp.contactUnderBond = v;
            } else if (!bond.next()) {
                a.fail("unknown keyword '" + a.peek() + "' (known: " + bond.known() + " " + kContactUnderBond + ")");
            }
        }
    }

    int count = 0;
    for (int ti = ilo; ti <= ihi; ti++)
        for (int tj = jlo; tj <= jhi; tj++) {
            const int i = std::min(ti, tj), j = std::max(ti, tj);
            pairs_[at(i, j)] = tp;
            pairs_[at(j, i)] = tp;
            buildModel(i, j);
            setflag[i][j] = setflag[j][i] = 1;
            count++;
        }
    if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients");
}

// Builds the core's models of types (i, j), i <= j, from pairs_ (stored at
// (i, j) only); the core validates, and its message names the parameter,
// its range and the value.
void PairGranbond::buildModel(int i, int j)
{
    const size_t k = at(i, j);
    const TypePair &tp = pairs_[k];
    granbond_voigt_model_free(voigt_[k]);
    granbond_bond_model_free(bond_[k]);
    voigt_[k] = nullptr;
    bond_[k] = nullptr;
    const std::string command = "pair_coeff " + std::to_string(i) + " " + std::to_string(j) + " ";
    if (granbond_voigt_model_new(&tp.voigt, &voigt_[k]) != GB_STATUS_OK)
        error->all(FLERR, command + kVoigt + ": " + coreReason());
    if (tp.hasBond && granbond_bond_model_new(&tp.bond, &bond_[k]) != GB_STATUS_OK)
        error->all(FLERR, command + kBond + ": " + coreReason());
}

}
}
