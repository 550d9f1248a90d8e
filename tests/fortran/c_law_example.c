/* A user C law in a shared library, for rs_law_load_c: a linear spring p = k h on the
 * overclosure h = rdisp(1) > 0, shear tau = c s on the accumulated slip rdisp(2:nDir),
 * and a descriptor naming its two properties and one state variable (the number of
 * calls that saw the contact closed). */
#include "rigidsurf/law.h"

int scaled_spring(const rs_law *law, rs_law_block *b, rs_error *err);

int scaled_spring(const rs_law *law, rs_law_block *b, rs_error *err)
{
    (void)law;
    (void)err;
    const double k = b->props[0], c = b->props[1];
    const int nd = b->nDir;
    for (int j = 0; j < b->nSlvNod; ++j) {
        const double h = RS_A2(b->rdisp, nd, 0, j);
        for (int i = 0; i < nd; ++i)
            RS_A2(b->stress, nd, i, j) = 0.0;
        b->sed[j] = 0.0;
        if (h > 0.0 && h < 0.5 * RS_MAXVAL) {
            RS_A2(b->stress, nd, 0, j) = k * h;
            for (int i = 1; i < nd; ++i)
                RS_A2(b->stress, nd, i, j) = c * RS_A2(b->rdisp, nd, i, j);
            b->statev[(size_t)j * (size_t)b->nStateVar] += 1.0;
        }
    }
    return RS_OK;
}

static const char *const scaled_spring_props[2] = {"k", "c"};

const rs_law scaled_spring_law = {
    .name = "scaled_spring",
    .nprops = 2,
    .nstatev = 1,
    .prop_names = scaled_spring_props,
    .update = scaled_spring,
};
