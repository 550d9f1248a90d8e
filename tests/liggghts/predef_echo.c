/* A user C law for the predef test: it echoes the predefined fields into the stress so
 * the fix's per-atom output shows what the law received. stress(1) = preDefSlv(1),
 * stress(3) = preDefSlv(2), stress(2) = the sum of dpreDefSlv(1) over the contact's
 * increments, kept in statev(1). */
#include "rigidsurf/law.h"

int predef_echo(const rs_law *law, rs_law_block *b, rs_error *err)
{
    (void)law;
    if (b->nPred != 2 || b->nStateVar < 1 || b->nDir != 3)
        return rs_error_set(err, RS_ERR_ARG,
                            "predef_echo: expected nPred = 2, statev >= 1, nDir = 3");
    for (int k = 0; k < b->nSlvNod; k++) {
        double *sv = b->statev + (size_t)k * (size_t)b->nStateVar;
        if (!b->setup)
            sv[0] += RS_A2(b->dpreDefSlv, b->nPred, 0, k);
        RS_A2(b->stress, 3, 0, k) = RS_A2(b->preDefSlv, b->nPred, 0, k);
        RS_A2(b->stress, 3, 1, k) = sv[0];
        RS_A2(b->stress, 3, 2, k) = RS_A2(b->preDefSlv, b->nPred, 1, k);
    }
    return RS_OK;
}
