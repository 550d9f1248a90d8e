/* A contact list for the tracker's tests, on fixed arrays of RS_TEST_MAXC contacts (no
 * allocation): rs_test_clist_init points an rs_contacts at them, rs_test_clist_add
 * appends one contact (curvatures 0, share and witness unset). */
#ifndef RS_TEST_CONTACTS_H
#define RS_TEST_CONTACTS_H

#include "rigidsurf/surface.h"

#include <string.h>

#define RS_TEST_MAXC 96

typedef struct rs_test_clist {
    int point[RS_TEST_MAXC], feature[RS_TEST_MAXC];
    double xm[3][RS_TEST_MAXC], nrm[3][RS_TEST_MAXC], t1[3][RS_TEST_MAXC],
        t2[3][RS_TEST_MAXC], dist[RS_TEST_MAXC], curv[2][RS_TEST_MAXC];
    rs_contacts c;
} rs_test_clist;

static inline void rs_test_clist_init(rs_test_clist *l)
{
    memset(l, 0, sizeof *l);
    l->c.cap = RS_TEST_MAXC;
    l->c.point = l->point;
    l->c.feature = l->feature;
    for (int d = 0; d < 3; d++) {
        l->c.xm[d] = l->xm[d];
        l->c.nrm[d] = l->nrm[d];
        l->c.t1[d] = l->t1[d];
        l->c.t2[d] = l->t2[d];
    }
    l->c.dist = l->dist;
    l->c.curv[0] = l->curv[0];
    l->c.curv[1] = l->curv[1];
}

static inline void rs_test_clist_add(rs_test_clist *l, int point, int feature,
                                     const double xm[3], const double n[3],
                                     const double t1[3], const double t2[3], double dist)
{
    const int k = l->c.n++;
    l->point[k] = point;
    l->feature[k] = feature;
    for (int d = 0; d < 3; d++) {
        l->xm[d][k] = xm[d];
        l->nrm[d][k] = n[d];
        l->t1[d][k] = t1[d];
        l->t2[d][k] = t2[d];
    }
    l->dist[k] = dist;
    l->curv[0][k] = 0.0;
    l->curv[1][k] = 0.0;
}

#endif
