/* rigidsurf: linear pressure-overclosure (Abaqus "softened contact, linear").
 * p = k h for the overclosure h = rdisp(1) > 0, p = 0 when open; no shear.
 * props: k (pressure per length, > 0). sed = k h^2 / 2. */
#include "builtin.h"

#include <math.h>

static int rs_linear_softening_init(const rs_law *law, const double *props, int nprops,
                                    rs_error *err)
{
    (void)nprops;
    if (!(props[0] > 0.0)) {
        return rs_error_set(err, RS_ERR_ARG, "law '%s': property 'k' must be > 0, got %g",
                            law->name, props[0]);
    }
    return RS_OK;
}

static int rs_linear_softening_update(const rs_law *law, rs_law_block *b, rs_error *err)
{
    (void)law;
    (void)err;
    const double k = b->props[0];
    const int nd = b->nDir;
    for (int c = 0; c < b->nSlvNod; ++c) {
        const double h = RS_A2(b->rdisp, nd, 0, c);
        rs_law_zero_contact(b, c);
        if (!RS_LAW_LEAVING(h) && h > 0.0) {
            RS_A2(b->stress, nd, 0, c) = k * h;
            b->sed[c] = 0.5 * k * h * h;
        }
    }
    return RS_OK;
}

static const char *const rs_linear_softening_props[] = {"k"};

/* p = k h: a stiffness k A. */
static double rs_linear_softening_critical_step(const rs_law *law, const double *p, int np,
                                                double R, double m, double A)
{
    (void)law, (void)R;
    const double K = np >= 1 ? p[0] * A : 0.0;
    return K > 0.0 && m > 0.0 ? 2.0 * sqrt(m / K) : 0.0;
}

const rs_law rs_law_linear_softening = {
    .name = "linear_softening",
    .nprops = 1,
    .nstatev = 0,
    .prop_names = rs_linear_softening_props,
    .init = rs_linear_softening_init,
    .update = rs_linear_softening_update,
    .critical_step = rs_linear_softening_critical_step,
    .reach = rs_law_reach_touching,
    .skips = RS_LAW_SKIPS_COORDMST,
};
