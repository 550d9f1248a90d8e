/* The slot layout follows what the law reads (track.h, rs_tracker.drop; law.h,
 * rs_law.skips): a tracker that drops the stress and the energies of the last call
 * keeps the same kinematics and state variables as one that keeps everything, gives the
 * law zeros where it dropped, and keeps what it keeps from one call to the next. The
 * reference is the same tracker with nothing dropped, on the same contacts. */
#include "rigidsurf/contact_block.h"
#include "rigidsurf/law.h"
#include "rigidsurf/track.h"
#include "rigidsurf/vec.h"
#include "rs_test.h"
#include "rs_test_contacts.h"

#include <math.h>
#include <stdlib.h>

#define NS 2
#define MAXC 4

/* Two spheres on the floor z = 0 (feature 0) and against the wall x = 0 (feature 1),
 * with their history in calloc'd slots of the tracker's size. */
typedef struct scene {
    rs_tracker tr;
    double x[2], y[2], z[2], vx[2], vy[2], vz[2], r[2];
    int id[2];
    double *dir[2], *hist[2];
    rs_particles p;
    rs_test_clist l;
    rs_track_out out;
} scene;

static void scene_init(scene *s, unsigned drop)
{
    memset(s, 0, sizeof *s);
    s->tr = (rs_tracker){2, NS, 3, 1e-3, drop};
    const int hs = rs_track_slot_size(&s->tr);
    for (int i = 0; i < 2; i++) {
        s->dir[i] = calloc(2, sizeof(double));
        s->hist[i] = calloc((size_t)2 * hs, sizeof(double));
        s->id[i] = 1 + i;
        s->r[i] = 0.01;
        s->x[i] = 0.0099 + 0.02 * i;
        s->y[i] = 0.0;
        s->z[i] = 0.0098;
        s->vx[i] = -0.1 - 0.05 * i;
        s->vy[i] = 0.3;
        s->vz[i] = -0.2;
    }
    s->p = (rs_particles){.n = 2,
                          .x = s->x,
                          .y = s->y,
                          .z = s->z,
                          .vx = s->vx,
                          .vy = s->vy,
                          .vz = s->vz,
                          .radius = s->r,
                          .id = s->id,
                          .dir = s->dir,
                          .hist = s->hist};
    rs_test_clist_init(&s->l);
}

static void scene_free(scene *s)
{
    for (int i = 0; i < 2; i++) {
        free(s->dir[i]);
        free(s->hist[i]);
    }
    rs_track_out_free(&s->out);
}

static void add_plane(scene *s, int point, int feature, const double n[3],
                      const double t1[3])
{
    const double x[3] = {s->x[point], s->y[point], s->z[point]};
    double t2[3];
    rs_cross3(n, t1, t2);
    const double dist = rs_dot3(x, n);
    const double xm[3] = {x[0] - dist * n[0], x[1] - dist * n[1], x[2] - dist * n[2]};
    rs_test_clist_add(&s->l, point, feature, xm, n, t1, t2, dist);
}

/* One call: the contacts of both spheres, the tracker, a stand-in law (stress, statev,
 * energies from the kinematics) and the commit. stress_in, sed_in: what the law got. */
static int step(scene *s, double dt, double *stress_in, double *statev_out, double *sed_in)
{
    const double nf[3] = {0, 0, 1}, af[3] = {1, 0, 0}, nw[3] = {1, 0, 0}, aw[3] = {0, 1, 0};
    s->l.c.n = 0;
    add_plane(s, 0, RS_FEATURE(RS_FEAT_FACE, 0), nf, af);
    add_plane(s, 0, RS_FEATURE(RS_FEAT_FACE, 1), nw, aw);
    add_plane(s, 1, RS_FEATURE(RS_FEAT_FACE, 0), nf, af);
    rs_error err;
    rs_error_clear(&err);
    if (rs_track_update(&s->tr, NULL, NULL, dt, &s->p, &s->l.c, &s->out, &err) != RS_OK)
        return -1;
    const int n = s->out.n;
    double stress[3 * MAXC], statev[NS * MAXC], sed[MAXC], fs[MAXC], fm[MAXC];
    rs_track_load(&s->tr, &s->out, stress, statev);
    rs_track_load_energy(&s->tr, &s->out, sed, fs, fm);
    for (int e = 0; e < n; e++) {
        for (int d = 0; d < 3; d++)
            stress_in[3 * e + d] = stress[3 * e + d];
        sed_in[e] = sed[e] + fs[e] + fm[e];
        /* the stand-in law: its state accumulates the slip; stress and energies follow */
        statev[NS * e] += RS_A2(s->out.drdisp, 3, 1, e);
        statev[NS * e + 1] += RS_A2(s->out.drdisp, 3, 2, e);
        stress[3 * e] = 1e3 * RS_A2(s->out.rdisp, 3, 0, e);
        stress[3 * e + 1] = 2e3 * statev[NS * e];
        stress[3 * e + 2] = 2e3 * statev[NS * e + 1];
        sed[e] = 5.0 + e, fs[e] = 0.25 * e, fm[e] = -0.5;
        for (int b = 0; b < NS; b++)
            statev_out[NS * e + b] = statev[NS * e + b];
    }
    rs_track_commit_energy(&s->tr, &s->out, sed, fs, fm);
    rs_track_commit(&s->tr, &s->out, stress, statev);
    for (int i = 0; i < 2; i++) {
        s->x[i] += s->vx[i] * dt;
        s->y[i] += s->vy[i] * dt;
        s->z[i] += s->vz[i] * dt * 0.01;
    }
    return n;
}

static void test_sizes(void)
{
    rs_tracker all = {4, 3, 3, 0.0, 0},
               lean = {4, 3, 3, 0.0, RS_DROP_STRESS | RS_DROP_ENERGY};
    ENSURE(rs_track_slot_size(&all) == RS_HIST_SIZE(3));
    ENSURE(rs_track_statev_at(&all) == RS_H_STATEV);
    ENSURE(rs_track_energy_at(&all) == RS_H_STATEV + 3);
    ENSURE(rs_track_slot_size(&lean) == RS_H_RDISP1 + 1 + 3);
    ENSURE(rs_track_statev_at(&lean) == RS_H_RDISP1 + 1);
    /* without the slip and rdisp1, the stress follows t1; with nothing else dropped the
     * slot is 3 shorter than a full one */
    rs_tracker noslip = {4, 3, 3, 0.0, RS_DROP_SLIP};
    ENSURE(rs_track_stress_at(&all) == RS_H_STRESS);
    ENSURE(rs_track_stress_at(&noslip) == RS_H_SLIP);
    ENSURE(rs_track_statev_at(&noslip) == RS_H_SLIP + 3);
    ENSURE(rs_track_energy_at(&noslip) == RS_H_SLIP + 3 + 3);
    ENSURE(rs_track_slot_size(&noslip) == RS_HIST_SIZE(3) - 3);
    /* hertz's slot: n, t1 and its 2 state variables, 8 values (one 64-byte line) */
    rs_tracker hertz = {4, 2, 3, 0.0, RS_DROP_STRESS | RS_DROP_ENERGY | RS_DROP_SLIP};
    ENSURE(rs_track_statev_at(&hertz) == 6 && rs_track_slot_size(&hertz) == 8);
    /* the built-in hertz and hooke read neither the stress nor the energies nor the slip
     * nor drdisp(1); a loaded law (skips 0) reads them all */
    const unsigned lean_law =
        RS_DROP_STRESS | RS_DROP_ENERGY | RS_DROP_COORDMST | RS_DROP_SLIP;
    ENSURE(rs_law_drops(rs_law_find("hertz")) == lean_law);
    ENSURE(rs_law_drops(rs_law_find("hooke")) == lean_law);
    /* no built-in law reads the closest master points */
    ENSURE(rs_law_drops(rs_law_find("bonded_interface")) == RS_DROP_COORDMST);
    ENSURE(rs_law_drops(rs_law_find("coulomb")) == RS_DROP_COORDMST);
    ENSURE(rs_law_drops(rs_law_find("linear_softening")) == RS_DROP_COORDMST);
    /* dropping them changes no slot */
    rs_tracker noxm = all;
    noxm.drop = RS_DROP_COORDMST;
    ENSURE(rs_track_slot_size(&noxm) == RS_HIST_SIZE(3));
    rs_law loaded;
    memset(&loaded, 0, sizeof loaded);
    ENSURE(rs_law_drops(&loaded) == 0);
    /* the slip goes only with drdisp(1): a law that reads either keeps both */
    loaded.skips = RS_LAW_SKIPS_SLIP;
    ENSURE(rs_law_drops(&loaded) == 0);
    loaded.skips = RS_LAW_SKIPS_DRDISP1;
    ENSURE(rs_law_drops(&loaded) == 0);
    loaded.skips = RS_LAW_SKIPS_SLIP | RS_LAW_SKIPS_DRDISP1;
    ENSURE(rs_law_drops(&loaded) == RS_DROP_SLIP);
}

static void test_dropped_fields(void)
{
    const unsigned drops[] = {RS_DROP_STRESS, RS_DROP_ENERGY,
                              RS_DROP_STRESS | RS_DROP_ENERGY, RS_DROP_SLIP,
                              RS_DROP_STRESS | RS_DROP_ENERGY | RS_DROP_SLIP};
    for (int v = 0; v < 5; v++) {
        scene ref, lean;
        scene_init(&ref, 0);
        scene_init(&lean, drops[v]);
        int same = 1, zeros = 1, kept = 1, calls = 0, differs = 0;
        for (int it = 0; it < 6; it++) {
            double sa[3 * MAXC], sb[3 * MAXC], va[NS * MAXC], vb[NS * MAXC], ea[MAXC],
                eb[MAXC];
            const int na = step(&ref, 1e-3, sa, va, ea), nb = step(&lean, 1e-3, sb, vb, eb);
            ENSURE(na == 3 && nb == 3);
            if (na != nb || na < 0)
                break;
            calls++;
            for (int e = 0; e < na; e++) {
                /* without the slip and rdisp1 (RS_DROP_SLIP), rdisp(2:3) is the slip
                 * increment drdisp(2:3) and drdisp(1) = -v_rel.n dt, as a new contact's */
                const int noslip = (drops[v] & RS_DROP_SLIP) != 0;
                for (int d = 0; d < 3; d++) {
                    const double rd = noslip && d > 0 ? RS_A2(ref.out.drdisp, 3, d, e)
                                                      : RS_A2(ref.out.rdisp, 3, d, e);
                    const double drd = noslip && d == 0
                                           ? -RS_A2(ref.out.vrel, 3, 0, e) * 1e-3
                                           : RS_A2(ref.out.drdisp, 3, d, e);
                    same &= RS_A2(lean.out.rdisp, 3, d, e) == rd;
                    same &= RS_A2(lean.out.drdisp, 3, d, e) == drd;
                    same &= ref.out.slot[e][RS_H_N + d] == lean.out.slot[e][RS_H_N + d];
                    same &= ref.out.slot[e][RS_H_T1 + d] == lean.out.slot[e][RS_H_T1 + d];
                }
                /* the accumulated slip differs from the increment from the second call on
                 */
                if (noslip && it > 0)
                    differs +=
                        RS_A2(ref.out.rdisp, 3, 1, e) != RS_A2(ref.out.drdisp, 3, 1, e);
                for (int d = 0; d < 4; d++)
                    same &= ref.out.drot[4 * e + d] == lean.out.drot[4 * e + d];
                for (int b = 0; b < NS; b++)
                    same &= va[NS * e + b] == vb[NS * e + b];
                /* what was dropped comes in as zero; what was kept as the reference's */
                for (int d = 0; d < 3; d++) {
                    if (drops[v] & RS_DROP_STRESS)
                        zeros &= sb[3 * e + d] == 0.0;
                    else
                        kept &= sb[3 * e + d] == sa[3 * e + d];
                }
                if (drops[v] & RS_DROP_ENERGY)
                    zeros &= eb[e] == 0.0;
                else
                    kept &= eb[e] == ea[e];
                /* from the second call on, the reference brought back what it kept */
                if (it > 0)
                    kept &= ea[e] == 5.0 + e + 0.25 * e - 0.5 && sa[3 * e] != 0.0;
            }
        }
        ENSURE(calls == 6);
        ENSURE(same);
        ENSURE(!(drops[v] & RS_DROP_SLIP) || differs > 0);
        ENSURE(zeros);
        ENSURE(kept);
        scene_free(&ref);
        scene_free(&lean);
    }
}

/* A tracker that drops coordMst writes everything else as one that keeps it, bit for
 * bit, and leaves coordmst as it was; the one that keeps it writes each contact's foot
 * on its plane. */
static void test_coordmst_dropped(void)
{
    scene ref, lean;
    scene_init(&ref, 0);
    scene_init(&lean, RS_DROP_COORDMST);
    double sa[3 * MAXC], sb[3 * MAXC], va[NS * MAXC], vb[NS * MAXC], ea[MAXC], eb[MAXC];
    ENSURE(step(&ref, 1e-3, sa, va, ea) == 3 && step(&lean, 1e-3, sb, vb, eb) == 3);
    const double sentinel = 12345.0;
    for (int k = 0; k < 3 * lean.out.cap; k++)
        lean.out.coordmst[k] = sentinel;
    int same = 1, untouched = 1, foot = 1;
    for (int it = 0; it < 4; it++) {
        /* the feet of this call's contacts, before step moves the spheres */
        const double x[2] = {ref.x[0], ref.x[1]}, y[2] = {ref.y[0], ref.y[1]},
                     z[2] = {ref.z[0], ref.z[1]};
        ENSURE(step(&ref, 1e-3, sa, va, ea) == 3 && step(&lean, 1e-3, sb, vb, eb) == 3);
        const int n = ref.out.n;
        for (int k = 0; k < 3 * n; k++) {
            same &= ref.out.rdisp[k] == lean.out.rdisp[k];
            same &= ref.out.drdisp[k] == lean.out.drdisp[k];
            same &= ref.out.vrel[k] == lean.out.vrel[k];
            same &= ref.out.coordslv[k] == lean.out.coordslv[k];
            untouched &= lean.out.coordmst[k] == sentinel;
        }
        for (int k = 0; k < 9 * n; k++)
            same &= ref.out.alocaldir[k] == lean.out.alocaldir[k];
        for (int k = 0; k < 4 * n; k++)
            same &= ref.out.drot[k] == lean.out.drot[k];
        for (int k = 0; k < NS * n; k++)
            same &= va[k] == vb[k];
        for (int e = 0; e < n; e++) {
            const int i = ref.out.point[e];
            const int floor = ref.out.feature[e] == RS_FEATURE(RS_FEAT_FACE, 0);
            /* floor z = 0: the foot is (x, y, 0); wall x = 0: (0, y, z) */
            const double want[3] = {floor ? x[i] : 0.0, y[i], floor ? 0.0 : z[i]};
            for (int d = 0; d < 3; d++)
                foot &= fabs(RS_A2(ref.out.coordmst, 3, d, e) - want[d]) < 1e-15;
        }
    }
    ENSURE(same);
    ENSURE(untouched);
    ENSURE(foot);
    scene_free(&ref);
    scene_free(&lean);
}

/* What a law's block call hands it: coordMst NULL for a law that skips it. */
static const double *seen_xm;
static int xm_probe(const rs_law *law, rs_law_block *b, rs_error *err)
{
    (void)law, (void)err;
    seen_xm = b->coordMst;
    for (int k = 0; k < 3 * b->nSlvNod; k++)
        b->stress[k] = 0.0;
    return RS_OK;
}

static void test_law_sees_no_coordmst(void)
{
    scene s;
    scene_init(&s, 0);
    double sa[3 * MAXC], va[NS * MAXC], ea[MAXC];
    ENSURE(step(&s, 1e-3, sa, va, ea) == 3);
    rs_contact_block cb;
    memset(&cb, 0, sizeof cb);
    cb.ndir = 3;
    cb.nstatev = NS;
    cb.area_mode = RS_AREA_NODE;
    rs_error err;
    rs_error_clear(&err);
    ENSURE(rs_cblock_reserve(&cb, MAXC, &err) == RS_OK);
    const double mass[2] = {1e-3, 2e-3};
    s.p.mass = mass;
    rs_cblock_inputs(&cb, &s.out, &s.p, 1e-3);
    rs_law probe;
    memset(&probe, 0, sizeof probe);
    probe.name = "xm_probe";
    probe.nprops = 0;
    probe.update = xm_probe;
    rs_law_block tmpl;
    rs_law_block_init(&tmpl);
    tmpl.nDir = 3;
    tmpl.nStateVar = NS;
    for (int v = 0; v < 2; v++) {
        probe.skips = v ? RS_LAW_SKIPS_COORDMST : 0u;
        seen_xm = (const double *)&seen_xm;
        ENSURE(rs_cblock_call(&cb, &probe, &tmpl, &s.out, &err) == RS_OK);
        if (v)
            ENSURE(seen_xm == NULL);
        else
            ENSURE(seen_xm == s.out.coordmst);
    }
    rs_cblock_free(&cb);
    scene_free(&s);
}

/* A slot built field by field in the order of track.h's layout (n, t1, slip, rdisp1,
 * stress, statev, energies), each field's values tagged 100 a + b; fields the drop mask
 * leaves out are skipped, and those of the drop flags `zero` are written as zeros.
 * Returns the length. */
static int tagged_slot(unsigned drop, int ns, double *h, unsigned zero)
{
    const int len[7] = {3, 3, 2, 1, 3, ns, 3};
    const unsigned gone[7] = {
        0, 0, RS_DROP_SLIP, RS_DROP_SLIP, RS_DROP_STRESS, 0, RS_DROP_ENERGY};
    int k = 0;
    for (int a = 0; a < 7; a++) {
        if (drop & gone[a])
            continue;
        for (int b = 0; b < len[a]; b++)
            h[k++] = (zero & gone[a]) ? 0.0 : 100.0 * (a + 1) + b;
    }
    return k;
}

/* rs_track_slot_convert between every pair of layouts: the fields both keep carried
 * over, those only the target keeps zero. */
static void test_slot_convert(void)
{
    const unsigned masks[] = {0u, RS_DROP_SLIP, RS_DROP_STRESS | RS_DROP_ENERGY,
                              RS_DROP_STRESS | RS_DROP_ENERGY | RS_DROP_SLIP,
                              RS_DROP_ENERGY | RS_DROP_SLIP};
    int ok = 1, pairs = 0;
    for (int ns = 0; ns <= 3; ns++)
        for (int a = 0; a < 5; a++)
            for (int b = 0; b < 5; b++) {
                const rs_tracker to = {4, ns, 3, 0.0, masks[b]};
                double src[32], want[32], got[32];
                const int ls = tagged_slot(masks[a], ns, src, 0);
                /* the target's fields that the source lacks are zero */
                const int lw = tagged_slot(masks[b], ns, want, masks[a] & ~masks[b]);
                rs_tracker from = to;
                from.drop = masks[a];
                ok &= ls == rs_track_slot_size(&from) && lw == rs_track_slot_size(&to);
                for (int k = 0; k < 32; k++)
                    got[k] = -1.0;
                rs_track_slot_convert(&to, masks[a], src, got);
                for (int k = 0; k < lw; k++)
                    ok &= got[k] == want[k];
                ok &= got[lw] == -1.0; /* nothing past the slot */
                pairs++;
            }
    ENSURE(pairs == 100);
    ENSURE(ok);
}

int main(void)
{
    RS_RUN(test_sizes);
    RS_RUN(test_slot_convert);
    RS_RUN(test_dropped_fields);
    RS_RUN(test_coordmst_dropped);
    RS_RUN(test_law_sees_no_coordmst);
    return rs_test_summary();
}
