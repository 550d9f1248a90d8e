#include "rigidsurf/types.h"

#include <stdarg.h>
#include <stdio.h>

int rs_error_set(rs_error *err, int code, const char *fmt, ...)
{
    if (err) {
        va_list ap;
        va_start(ap, fmt);
        err->code = code;
        vsnprintf(err->msg, sizeof err->msg, fmt, ap);
        va_end(ap);
    }
    return code;
}

void rs_error_clear(rs_error *err)
{
    if (err) {
        err->code = RS_OK;
        err->msg[0] = '\0';
    }
}
