/* rigidsurf: the registry of built-in interface laws (name -> descriptor). */
#include "laws/builtin.h"

#include <ctype.h>

static const rs_law *const rs_law_table[] = {
    &rs_law_bonded_interface, &rs_law_linear_softening, &rs_law_hertz, &rs_law_hooke,
    &rs_law_coulomb,
};

#define RS_LAW_TABLE_COUNT ((int)(sizeof rs_law_table / sizeof rs_law_table[0]))

static int rs_law_name_equal(const char *a, const char *b)
{
    for (; *a && *b; ++a, ++b) {
        if (tolower((unsigned char)*a) != tolower((unsigned char)*b)) {
            return 0;
        }
    }
    return *a == *b;
}

const rs_law *rs_law_find(const char *name)
{
    if (!name) {
        return NULL;
    }
    for (int i = 0; i < RS_LAW_TABLE_COUNT; ++i) {
        if (rs_law_name_equal(rs_law_table[i]->name, name)) {
            return rs_law_table[i];
        }
    }
    return NULL;
}

int rs_law_count(void)
{
    return RS_LAW_TABLE_COUNT;
}

const rs_law *rs_law_at(int i)
{
    return i >= 0 && i < RS_LAW_TABLE_COUNT ? rs_law_table[i] : NULL;
}
