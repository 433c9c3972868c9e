// The words of a coefficient command (`pair_coeff I J voigt ...
// bond/nonlinear ...`, `bond_coeff N ...`) read into the core's parameter
// tables: a keyword is a row of the model's table (its value written as the
// row's kind says) or one of the model's phrases: opening words, values for
// the rows the phrase names, and rows the phrase sets itself (granbond.h,
// granbond_*_phrase_info). The grammar's rules are the core's phrases; this
// file only looks words up.
#ifndef GRANBOND_LAMMPS_COEFF_WORDS_H
#define GRANBOND_LAMMPS_COEFF_WORDS_H

#include "core_message.h"
#include "granbond.h"

#include "error.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

namespace granbond {
namespace lammps {
namespace words {

inline std::vector<std::string> split(const char *s)
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
    // `first`: the first word after the command's own (type pair or bond
    // type); `command`: the command and those words, as errors name it
    Args(int narg, char **arg, LAMMPS_NS::Error *error, int first, const std::string &command) :
        narg_(narg), arg_(arg), error_(error), at_(first), command_(command)
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
    LAMMPS_NS::Error *error_;
    int at_;
    std::string command_, clause_;
};

inline bool isNumber(const std::string &s)
{
    if (s.empty()) return false;
    char *end = nullptr;
    std::strtod(s.c_str(), &end);
    return end != s.c_str() && *end == '\0';
}

// A deck's value for a row of `kind`, as the core takes it (switches 1 or 0,
// steps as exact doubles).
inline double value(Args &a, GbParameterKind kind, const std::string &what)
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

    // The words that set each row on this line (empty: not set by the deck).
    const std::vector<std::string> &givenBy() const { return givenBy_; }

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

// The rest of the line as bond law `law`'s clause (pair_coeff's
// bond/nonlinear or bond/linear, bond_coeff's), into `params` holding the
// law's defaults; returns the words that set each row (empty: not set).
inline std::vector<std::string> readBondClause(Args &a, const char *law, GbBondParams &params)
{
    Clause<GbBondParams> bond(a, law, &granbond_bond_parameter_info, &granbond_bond_phrase_info,
                              &granbond_bond_params_set, params);
    while (!a.done())
        if (!bond.next()) a.fail("unknown keyword '" + a.peek() + "' (known: " + bond.known() + ")");
    return bond.givenBy();
}

}
}
}

#endif
