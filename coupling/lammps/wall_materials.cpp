/* fix wall/rigid in LAMMPS: the material properties on the fix line (wall_materials.h). */
#include "wall_materials.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace
{

/* The keywords: per atom type (N values) or one value. */
struct Keyword {
    const char *name;
    bool per_type;
};
const Keyword kKeywords[] = {{"youngsModulus", true},
                             {"poissonsRatio", true},
                             {"coefficientRestitution", true},
                             {"coefficientFriction", true},
                             {"k_finnie", true},
                             {"characteristicVelocity", false}};

const Keyword *find(const std::string &w)
{
    for (const Keyword &k : kKeywords)
        if (w == k.name)
            return &k;
    return nullptr;
}

/* The asker as the message names it: "law hertz" of "fix wall/rigid (law hertz)". */
std::string asker(const char *who)
{
    const std::string w = who, pre = "fix wall/rigid (";
    if (w.compare(0, pre.size(), pre) == 0 && w.back() == ')')
        return w.substr(pre.size(), w.size() - pre.size() - 1);
    return w;
}

bool number(const std::string &s, double *v)
{
    if (s.empty())
        return false;
    char *end = nullptr;
    errno = 0;
    *v = std::strtod(s.c_str(), &end);
    return end && *end == '\0' && errno == 0 && std::isfinite(*v);
}

} // namespace

std::string WallMaterials::take(std::vector<std::string> &words, int ntypes)
{
    ntypes_ = ntypes;
    std::vector<std::string> rest;
    for (size_t k = 0; k < words.size();) {
        const Keyword *kw = find(words[k]);
        if (!kw) {
            rest.push_back(words[k++]);
            continue;
        }
        const int n = kw->per_type ? ntypes : 1;
        const std::string what =
            kw->per_type ? std::to_string(n) + " numbers, one per atom type (create_box " +
                               std::to_string(ntypes) + ")"
                         : std::string("one number");
        std::vector<double> v((size_t)n);
        for (int t = 0; t < n; t++) {
            const size_t at = k + 1 + (size_t)t;
            if (at >= words.size() || !number(words[at], &v[(size_t)t]))
                return "keyword '" + words[k] + "' expects " + what + ", got " +
                       (at < words.size() ? "'" + words[at] + "'" : "(end of line)");
        }
        double extra;
        const size_t next = k + 1 + (size_t)n;
        if (next < words.size() && number(words[next], &extra))
            return "keyword '" + words[k] + "' expects " + what + ", got more";
        if (values_.count(words[k]))
            return "keyword '" + words[k] + "' given twice";
        values_[words[k]] = v;
        k = next;
    }
    words.swap(rest);
    return "";
}

int WallMaterials::lookup(const char *name, int i, int j, int wall_type, int required,
                          const char *who, double *value, rs_error *err) const
{
    const auto it = values_.find(name);
    const Keyword *kw = find(name);
    if (it == values_.end()) {
        if (!required)
            return RS_ERR_NOTFOUND;
        const std::string by = asker(who);
        if (!kw)
            return rs_error_set(err, RS_ERR_ARG,
                                "%s reads the material property '%s', which LAMMPS does "
                                "not give",
                                by.c_str(), name);
        if (!kw->per_type)
            return rs_error_set(err, RS_ERR_ARG,
                                "%s reads the material property %s: give '%s V' in the fix",
                                by.c_str(), name, name);
        return rs_error_set(err, RS_ERR_ARG,
                            "%s reads the material property %s: give '%s V1 .. V%d' in the "
                            "fix, one value per atom type%s",
                            by.c_str(), name, name, ntypes_,
                            j > 0 ? " (each type's against the wall)"
                                  : " (the wall's: its type's)");
    }
    const std::vector<double> &v = it->second;
    if (!kw->per_type) {
        *value = v[0];
        return RS_OK;
    }
    /* a pair property: the particle's type is the one that is not the wall's */
    const int t = j > 0 && i == wall_type ? j : i;
    if (t < 1 || t > (int)v.size())
        return RS_ERR_NOTFOUND;
    *value = v[(size_t)t - 1];
    return RS_OK;
}
