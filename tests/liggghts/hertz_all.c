/* The built-in hertz law as a loaded C law (`law user LIB hertz_all statev 2`): a loaded
 * law declares nothing it skips, so its contacts' slots keep the last call's stress and
 * energies, which the built-in hertz's do not (test_restart.py: a restart file written
 * with it is read by law hertz). */
#include "rigidsurf/law.h"

int hertz_all(const rs_law *law, rs_law_block *b, rs_error *err);

int hertz_all(const rs_law *law, rs_law_block *b, rs_error *err)
{
    (void)law;
    const rs_law *h = rs_law_find("hertz");
    return h->update(h, b, err);
}
