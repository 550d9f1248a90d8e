/* Loader failures name the library and the missing symbol (dlerror text included);
 * nothing is left open or half-filled. */
#include "rigidsurf/law.h"
#include "rs_test.h"

static const char *missing = "/nonexistent/dir/librs_missing_law.so";

static void test_missing_library_names_path(void)
{
    rs_law law;
    rs_error err;
    ENSURE(rs_law_load_c(missing, "f", &law, &err) == RS_ERR_IO);
    ENSURE(strstr(err.msg, missing) != NULL);
    ENSURE(strstr(err.msg, "No such file") != NULL); /* the dynamic loader's text */
    ENSURE(rs_law_load_vuinter(missing, &law, &err) == RS_ERR_IO);
    ENSURE(strstr(err.msg, missing) != NULL);
    ENSURE(rs_law_load_uinter(missing, NULL, &law, &err) == RS_ERR_IO);
    ENSURE(strstr(err.msg, missing) != NULL);
    ENSURE(rs_law_load_uinter_v6(missing, NULL, &law, &err) == RS_ERR_IO);
    ENSURE(rs_law_load_fric(missing, rs_law_find("linear_softening"), &law, &err) ==
           RS_ERR_IO);
    ENSURE(strstr(err.msg, missing) != NULL);
}

/* libm is always there and exports none of the routines. */
static void test_missing_symbol_names_library_and_symbol(void)
{
    rs_law law;
    rs_error err;
    const char *libm = "libm.so.6";
    ENSURE(rs_law_load_vuinter(libm, &law, &err) == RS_ERR_NOTFOUND);
    ENSURE(strstr(err.msg, libm) && strstr(err.msg, "vuinter_") &&
           strstr(err.msg, "'vuinter'"));
    ENSURE(strstr(err.msg, "undefined symbol") != NULL);
    ENSURE(rs_law_load_uinter(libm, NULL, &law, &err) == RS_ERR_NOTFOUND);
    ENSURE(strstr(err.msg, libm) && strstr(err.msg, "uinter_"));
    ENSURE(rs_law_load_fric(libm, rs_law_find("hertz"), &law, &err) == RS_ERR_NOTFOUND);
    ENSURE(strstr(err.msg, libm) && strstr(err.msg, "fric_"));
    ENSURE(rs_law_load_c(libm, "my_law_update", &law, &err) == RS_ERR_NOTFOUND);
    ENSURE(strstr(err.msg, libm) && strstr(err.msg, "my_law_update"));
}

static void test_bad_arguments_are_rejected(void)
{
    rs_law law;
    rs_error err;
    ENSURE(rs_law_load_fric("libm.so.6", NULL, &law, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "normal law") != NULL);
    ENSURE(rs_law_load_c(NULL, "f", &law, &err) == RS_ERR_ARG);
    ENSURE(rs_law_load_c("libm.so.6", "", &law, &err) == RS_ERR_ARG);
    ENSURE(rs_law_load_vuinter("libm.so.6", NULL, &err) == RS_ERR_ARG);
    memset(&law, 0, sizeof law);
    rs_law_unload(&law); /* a zeroed law unloads as a no-op */
    rs_law_unload(NULL);
}

int main(void)
{
    RS_RUN(test_missing_library_names_path);
    RS_RUN(test_missing_symbol_names_library_and_symbol);
    RS_RUN(test_bad_arguments_are_rejected);
    return rs_test_summary();
}
