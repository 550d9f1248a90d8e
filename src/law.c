/* rigidsurf: calling interface laws: property checks, the guarded block call, default
 * stiffness and conductance, and block defaults (Abaqus VUINTER conventions). */
#include "rigidsurf/law.h"
#include "laws/builtin.h"
#include "rigidsurf/track.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

/* Read-only defaults for rs_law_block_init, valid for up to RS_BLOCK contacts. */
static const double rs_law_ones[RS_BLOCK] = {
#define RS_ONE8 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0
#define RS_ONE32 RS_ONE8, RS_ONE8, RS_ONE8, RS_ONE8
    RS_ONE32, RS_ONE32, RS_ONE32, RS_ONE32
#undef RS_ONE32
#undef RS_ONE8
};
static const double rs_law_zeros[RS_BLOCK];
static const int rs_law_master_uid[1] = {0};

static const char *rs_law_name(const rs_law *law)
{
    return law && law->name ? law->name : "(unnamed)";
}

/* "'E' (property 2)" or "property 2" when the law has no names. */
static void rs_law_prop_label(const rs_law *law, int i, char *buf, size_t size)
{
    if (law->prop_names && law->nprops > i && law->prop_names[i]) {
        snprintf(buf, size, "'%s' (property %d)", law->prop_names[i], i + 1);
    } else {
        snprintf(buf, size, "property %d", i + 1);
    }
}

int rs_law_check_props(const rs_law *law, const double *props, int nprops, rs_error *err)
{
    if (!law) {
        return rs_error_set(err, RS_ERR_ARG, "law is NULL");
    }
    if (nprops < 0 || (nprops > 0 && !props)) {
        return rs_error_set(err, RS_ERR_ARG, "law '%s': %d properties but no values",
                            rs_law_name(law), nprops);
    }
    if (law->nprops >= 0 && nprops != law->nprops) {
        char names[256] = "";
        size_t used = 0;
        for (int i = 0; law->prop_names && i < law->nprops && used < sizeof names; ++i) {
            int w = snprintf(names + used, sizeof names - used, "%s%s", i ? ", " : "",
                             law->prop_names[i]);
            if (w < 0) {
                break;
            }
            used += (size_t)w;
        }
        return rs_error_set(err, RS_ERR_ARG, "law '%s' expects %d properties%s%s%s, got %d",
                            rs_law_name(law), law->nprops, names[0] ? " (" : "", names,
                            names[0] ? ")" : "", nprops);
    }
    for (int i = 0; i < nprops; ++i) {
        if (!isfinite(props[i])) {
            char label[96];
            rs_law_prop_label(law, i, label, sizeof label);
            return rs_error_set(err, RS_ERR_ARG,
                                "law '%s': %s is %g, expected a finite number",
                                rs_law_name(law), label, props[i]);
        }
    }
    if (law->init) {
        return law->init(law, props, nprops, err);
    }
    return RS_OK;
}

static const char *rs_feature_kind(int f)
{
    switch (RS_FEATURE_TYPE(f)) {
    case RS_FEAT_FACE:
        return "face";
    case RS_FEAT_EDGE:
        return "edge";
    case RS_FEAT_VERTEX:
        return "vertex";
    default:
        return "feature";
    }
}

int rs_law_nonfinite_error(const rs_law *law, int pid, int f, int k, int n,
                           const char *what, double value, rs_error *err)
{
    if (f < 0) {
        return rs_error_set(err, RS_ERR_NONFINITE,
                            "law '%s' returned %s = %g for particle %d, feature %d "
                            "(contact %d of %d)",
                            rs_law_name(law), what, value, pid, f, k + 1, n);
    }
    return rs_error_set(err, RS_ERR_NONFINITE,
                        "law '%s' returned %s = %g for particle %d, feature %d (%s %d) "
                        "(contact %d of %d)",
                        rs_law_name(law), what, value, pid, f, rs_feature_kind(f),
                        RS_FEATURE_INDEX(f), k + 1, n);
}

static int rs_law_nonfinite(const rs_law *law, const rs_law_block *b, int k,
                            const char *what, double value, rs_error *err)
{
    return rs_law_nonfinite_error(law, b->jSlvUid[k],
                                  b->jConMstid[(size_t)k * (size_t)b->nFacNod], k,
                                  b->nSlvNod, what, value, err);
}

static int rs_law_check_block(const rs_law *law, const rs_law_block *b, rs_error *err)
{
    const char *name = rs_law_name(law);
    if (!law->update) {
        return rs_error_set(err, RS_ERR_ARG, "law '%s' has no update function", name);
    }
    if (b->nSlvNod < 0 || b->nSlvNod > RS_BLOCK) {
        return rs_error_set(err, RS_ERR_ARG,
                            "law '%s': block of %d contacts, expected 0..%d", name,
                            b->nSlvNod, RS_BLOCK);
    }
    if (b->nDir != 2 && b->nDir != 3) {
        return rs_error_set(err, RS_ERR_ARG, "law '%s': nDir = %d, expected 2 or 3", name,
                            b->nDir);
    }
    if (b->nFacNod < 1) {
        return rs_error_set(err, RS_ERR_ARG, "law '%s': nFacNod = %d, expected >= 1", name,
                            b->nFacNod);
    }
    if (law->nprops >= 0 && b->nProps != law->nprops) {
        return rs_error_set(err, RS_ERR_ARG,
                            "law '%s': block has %d properties, expected %d", name,
                            b->nProps, law->nprops);
    }
    if (b->nStateVar < law->nstatev) {
        return rs_error_set(err, RS_ERR_ARG,
                            "law '%s': block has %d state variables, the law needs %d",
                            name, b->nStateVar, law->nstatev);
    }
    struct {
        const void *p;
        const char *what;
    } need[] = {
        {b->jSlvUid, "jSlvUid"}, {b->jConMstid, "jConMstid"},
        {b->rdisp, "rdisp"},     {b->drdisp, "drdisp"},
        {b->drot, "drot"},       {b->stress, "stress"},
        {b->fluxSlv, "fluxSlv"}, {b->fluxMst, "fluxMst"},
        {b->sed, "sed"},         {b->sfd, "sfd"},
        {b->scd, "scd"},         {b->spd, "spd"},
        {b->svd, "svd"},
    };
    for (size_t i = 0; i < sizeof need / sizeof need[0]; ++i) {
        if (!need[i].p) {
            return rs_error_set(err, RS_ERR_ARG, "law '%s': block array %s is NULL", name,
                                need[i].what);
        }
    }
    if ((law->sets & RS_LAW_SETS_FORCE) && (!b->force || !b->torque)) {
        return rs_error_set(
            err, RS_ERR_ARG,
            "law '%s': a force law's block arrays force and torque are NULL", name);
    }
    if (b->nStateVar > 0 && !b->statev) {
        return rs_error_set(err, RS_ERR_ARG, "law '%s': block array statev is NULL", name);
    }
    if (b->nProps > 0 && !b->props) {
        return rs_error_set(err, RS_ERR_ARG, "law '%s': block array props is NULL", name);
    }
    return RS_OK;
}

int rs_law_call(const rs_law *law, rs_law_block *b, rs_error *err)
{
    if (!law || !b) {
        return rs_error_set(err, RS_ERR_ARG, "rs_law_call: law or block is NULL");
    }
    int rc = rs_law_check_block(law, b, err);
    if (rc != RS_OK) {
        return rc;
    }
    const int n = b->nSlvNod;
    /* Write-only outputs start at zero, so a law sets only the energies it has. */
    if (!(law->sets & RS_LAW_SETS_ENERGIES))
        for (int k = 0; k < n; ++k) {
            b->sfd[k] = 0.0;
            b->scd[k] = 0.0;
            b->spd[k] = 0.0;
            b->svd[k] = 0.0;
        }
    rc = law->update(law, b, err);
    if (rc != RS_OK) {
        return rc;
    }
    /* One branch-free pass says whether anything is NaN or Inf; only then is the first
     * offender looked for. */
    const int nsd = n * b->nDir;
    uint64_t acc = 0;
    for (int k = 0; k < nsd; ++k) {
        acc |= rs_nonfinite_bit(b->stress[k]);
    }
    for (int k = 0; k < n; ++k) {
        acc |= rs_nonfinite_bit(b->fluxSlv[k]) | rs_nonfinite_bit(b->fluxMst[k]);
    }
    const int force = (law->sets & RS_LAW_SETS_FORCE) != 0;
    for (int k = 0; force && k < 3 * n; ++k) {
        acc |= rs_nonfinite_bit(b->force[k]) | rs_nonfinite_bit(b->torque[k]);
    }
    const int bad = (int)(acc >> 63);
    if (!bad) {
        return RS_OK;
    }
    static const char *const sname[3] = {"stress(1)", "stress(2)", "stress(3)"};
    for (int k = 0; k < n; ++k) {
        for (int i = 0; i < b->nDir; ++i) {
            double s = RS_A2(b->stress, b->nDir, i, k);
            if (!isfinite(s)) {
                return rs_law_nonfinite(law, b, k, sname[i], s, err);
            }
        }
        if (!isfinite(b->fluxSlv[k])) {
            return rs_law_nonfinite(law, b, k, "fluxSlv", b->fluxSlv[k], err);
        }
        if (!isfinite(b->fluxMst[k])) {
            return rs_law_nonfinite(law, b, k, "fluxMst", b->fluxMst[k], err);
        }
        static const char *const fname[6] = {"force(1)",  "force(2)",  "force(3)",
                                             "torque(1)", "torque(2)", "torque(3)"};
        for (int i = 0; force && i < 6; ++i) {
            const double v = i < 3 ? b->force[3 * k + i] : b->torque[3 * k + i - 3];
            if (!isfinite(v)) {
                return rs_law_nonfinite(law, b, k, fname[i], v, err);
            }
        }
    }
    return RS_OK;
}

double rs_law_default_stiffness(double mass, double area, double dt)
{
    if (!(mass > 0.0) || !(area > 0.0) || !(dt > 0.0)) {
        return 0.0;
    }
    /* Central differences on m x'' = -k A x are stable for dt < 2 sqrt(m / (k A)). */
    return 0.1 * 4.0 * mass / (area * dt * dt);
}

double rs_law_reach_touching(const rs_law *law, const double *props, int nprops)
{
    (void)law, (void)props, (void)nprops;
    return 0.0;
}

double rs_rayleigh_time(double radius, double mass, double young, double poisson)
{
    if (!(radius > 0.0) || !(mass > 0.0) || !(young > 0.0) ||
        !(poisson > -1.0 && poisson < 0.5))
        return 0.0;
    const double pi = 3.14159265358979323846;
    const double rho = 3.0 * mass / (4.0 * pi * radius * radius * radius);
    const double shear = young / (2.0 * (1.0 + poisson));
    return pi * radius * sqrt(rho / shear) / (0.1631 * poisson + 0.8766);
}

double rs_law_default_conductance(double heat_capacity, double area, double dt)
{
    if (!(heat_capacity > 0.0) || !(area > 0.0) || !(dt > 0.0)) {
        return 0.0;
    }
    /* Forward Euler on C T' = -h A (T - Tw) is monotone for h A dt / C <= 1. */
    return 0.1 * heat_capacity / (area * dt);
}

void rs_law_block_set_name(char dst[RS_LAW_NAMELEN], const char *s)
{
    size_t len = s ? strlen(s) : 0;
    if (len > RS_LAW_NAMELEN) {
        len = RS_LAW_NAMELEN;
    }
    if (len) {
        memcpy(dst, s, len);
    }
    memset(dst + len, ' ', RS_LAW_NAMELEN - len);
}

void rs_law_block_init(rs_law_block *b)
{
    memset(b, 0, sizeof *b);
    b->kStep = 1;
    b->kInc = 1;
    b->nFacNod = 1;
    b->nMstNod = 1;
    b->nTemp = 1;
    b->nPred = 0;
    b->numDefTfv = 1;
    rs_law_block_set_name(b->surfInt, NULL);
    rs_law_block_set_name(b->surfSlv, NULL);
    rs_law_block_set_name(b->surfMst, NULL);
    b->jMstUid = rs_law_master_uid;
    b->shape = rs_law_ones;
    b->areaSlv = rs_law_ones;
    b->tempSlv = rs_law_zeros;
    b->dtempSlv = rs_law_zeros;
    b->preDefSlv = rs_law_zeros;
    b->dpreDefSlv = rs_law_zeros;
    b->tempMst = rs_law_zeros;
    b->dtempMst = rs_law_zeros;
    b->preDefMst = rs_law_zeros;
    b->dpreDefMst = rs_law_zeros;
}

void rs_law_requests_clear(rs_law_requests *r)
{
    memset(r, 0, sizeof *r);
    r->pnewdt_min = 1.0;
    r->pnewdt_particle = r->pnewdt_feature = -1;
    r->step_min = INFINITY;
}

void rs_law_requests_merge(rs_law_requests *dst, const rs_law_requests *src)
{
    if (src->pnewdt_calls > 0 && src->pnewdt_min < dst->pnewdt_min) {
        dst->pnewdt_min = src->pnewdt_min;
        dst->pnewdt_particle = src->pnewdt_particle;
        dst->pnewdt_feature = src->pnewdt_feature;
    }
    dst->pnewdt_calls += src->pnewdt_calls;
    if (src->step_min < dst->step_min) {
        dst->step_min = src->step_min;
        dst->step_what = src->step_what;
    }
}

unsigned rs_law_drops(const rs_law *law)
{
    unsigned drop = 0;
    if (law && (law->skips & RS_LAW_SKIPS_STRESS))
        drop |= RS_DROP_STRESS;
    if (law && (law->skips & RS_LAW_SKIPS_ENERGY))
        drop |= RS_DROP_ENERGY;
    if (law && (law->skips & RS_LAW_SKIPS_COORDMST))
        drop |= RS_DROP_COORDMST;
    const unsigned slip = RS_LAW_SKIPS_SLIP | RS_LAW_SKIPS_DRDISP1;
    if (law && (law->skips & slip) == slip)
        drop |= RS_DROP_SLIP;
    return drop;
}

int rs_law_stress_in(const rs_law *law)
{
    return !(law && (law->skips & RS_LAW_SKIPS_STRESS) && (law->sets & RS_LAW_SETS_STRESS));
}
