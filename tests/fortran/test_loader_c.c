/* rs_law_load_c: a user C law in a shared library, with and without its exported
 * descriptor, against the closed form p = k h, tau = c s. */
#include "rigidsurf/law.h"
#include "rs_test.h"
#include "test_law_fixture.h"

static law_fix f;

static void test_c_law_descriptor_gives_name_props_statev(void)
{
    rs_law law;
    rs_error err;
    ENSURE(rs_law_load_c(RS_C_LAW_EXAMPLE_LIB, "scaled_spring", &law, &err) == RS_OK);
    ENSURE(strcmp(law.name, "scaled_spring") == 0);
    ENSURE(law.nprops == 2 && law.nstatev == 1);
    ENSURE(strcmp(law.prop_names[1], "c") == 0);
    double bad[1] = {1.0};
    ENSURE(rs_law_check_props(&law, bad, 1, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "expects 2") != NULL);
    double props[2] = {2e5, 3e4};
    law_fix_init(&f, &law, props, 2, 3, 3);
    for (int k = 0; k < 3; ++k) {
        RS_A2(f.rdisp, 3, 0, k) = 1e-5 * (k - 1);
        RS_A2(f.rdisp, 3, 1, k) = 2e-6;
        RS_A2(f.rdisp, 3, 2, k) = -1e-6;
    }
    for (int rep = 0; rep < 2; ++rep) {
        ENSURE(rs_law_call(&law, &f.b, &err) == RS_OK);
    }
    ENSURE(RS_A2(f.stress, 3, 0, 0) == 0.0 && f.statev[0] == 0.0);
    ENSURE_REL(RS_A2(f.stress, 3, 0, 2), 2e5 * 1e-5, 1e-15);
    ENSURE_REL(RS_A2(f.stress, 3, 1, 2), 3e4 * 2e-6, 1e-15);
    ENSURE_REL(RS_A2(f.stress, 3, 2, 2), -3e4 * 1e-6, 1e-15);
    ENSURE(f.statev[2] == 2.0);
    rs_law_unload(&law);
    ENSURE(law.update == NULL && law.name == NULL);
}

static void test_c_law_missing_symbol_names_library_and_symbol(void)
{
    rs_law law;
    rs_error err;
    ENSURE(rs_law_load_c(RS_C_LAW_EXAMPLE_LIB, "no_such_law", &law, &err) ==
           RS_ERR_NOTFOUND);
    ENSURE(strstr(err.msg, "no_such_law") != NULL);
    ENSURE(strstr(err.msg, "rs_c_law_example") != NULL);
    /* the Fortran libraries have no vuinter/uinter/fric of the other kinds */
    ENSURE(rs_law_load_vuinter(RS_FRIC_COULOMB_LIB, &law, &err) == RS_ERR_NOTFOUND);
    ENSURE(strstr(err.msg, "vuinter_") && strstr(err.msg, "rs_fric_coulomb"));
    ENSURE(rs_law_load_fric(RS_VUINTER_BONDED_LIB, rs_law_find("hertz"), &law, &err) ==
           RS_ERR_NOTFOUND);
    ENSURE(strstr(err.msg, "fric_") && strstr(err.msg, "rs_vuinter_bonded"));
    ENSURE(rs_law_load_uinter(RS_VUINTER_BONDED_LIB, NULL, &law, &err) == RS_ERR_NOTFOUND);
    ENSURE(strstr(err.msg, "uinter_") && strstr(err.msg, "rs_vuinter_bonded"));
}

int main(void)
{
    RS_RUN(test_c_law_descriptor_gives_name_props_statev);
    RS_RUN(test_c_law_missing_symbol_names_library_and_symbol);
    return rs_test_summary();
}
