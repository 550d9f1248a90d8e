/* One contact's loads from the law's stress, shared by the loads kernel
 * (contact_loads.c) and hertz's fused kernel (laws/hertz_fused.c), so that both compute them with the
 * same operations in the same order. Internal to the library. */
#ifndef RIGIDSURF_LOAD_CONTACT_H
#define RIGIDSURF_LOAD_CONTACT_H

#include "rigidsurf/contact_block.h"

#include "rs_compiler.h"

/* The wall's force and moment about its origin, summed over contacts. */
typedef struct rs_wall_acc {
    double fw0, fw1, fw2, mw0, mw1, mw2;
} rs_wall_acc;

/* The force on the particle, F = A (s1 n - s2 t1 - s3 t2), from the stress s(3) and the
 * frame's columns L = (n, t1, t2) (9). */
RS_INLINE void rs_load_force3(double A, const double *s, const double *L, double F[3])
{
    F[0] = A * (s[0] * L[0] - s[1] * L[3] - s[2] * L[6]);
    F[1] = A * (s[0] * L[1] - s[1] * L[4] - s[2] * L[7]);
    F[2] = A * (s[0] * L[2] - s[1] * L[5] - s[2] * L[8]);
}

/* F acting at the contact point x: its torque T about the particle's centre c, and its
 * moment M = (x - o) x F about the wall's origin o. */
RS_INLINE void rs_load_torques(const double F[3], const double x[3], const double c[3],
                               const double o[3], double T[3], double M[3])
{
    const double r0 = x[0] - c[0], r1 = x[1] - c[1], r2 = x[2] - c[2];
    T[0] = r1 * F[2] - r2 * F[1];
    T[1] = r2 * F[0] - r0 * F[2];
    T[2] = r0 * F[1] - r1 * F[0];
    const double rw0 = x[0] - o[0], rw1 = x[1] - o[1], rw2 = x[2] - o[2];
    M[0] = rw1 * F[2] - rw2 * F[1];
    M[1] = rw2 * F[0] - rw0 * F[2];
    M[2] = rw0 * F[1] - rw1 * F[0];
}

/* The reaction -F and its moment -M onto the wall's sums. */
RS_INLINE void rs_wall_acc_take(rs_wall_acc *acc, const double F[3], const double M[3])
{
    acc->fw0 -= F[0], acc->fw1 -= F[1], acc->fw2 -= F[2];
    acc->mw0 -= M[0], acc->mw1 -= M[1], acc->mw2 -= M[2];
}

/* A force law's contact (RS_LAW_SETS_FORCE): F = A f and T = A t from its force f and
 * torque t, and the moment about the wall's origin o of F at the particle's centre c with
 * T, M = (c - o) x F + T. */
RS_INLINE void rs_load_force_law(double A, const double f[3], const double t[3],
                                 const double c[3], const double o[3], double F[3],
                                 double T[3], double M[3])
{
    F[0] = A * f[0], F[1] = A * f[1], F[2] = A * f[2];
    T[0] = A * t[0], T[1] = A * t[1], T[2] = A * t[2];
    const double r0 = c[0] - o[0], r1 = c[1] - o[1], r2 = c[2] - o[2];
    M[0] = r1 * F[2] - r2 * F[1] + T[0];
    M[1] = r2 * F[0] - r0 * F[2] + T[1];
    M[2] = r0 * F[1] - r1 * F[0] + T[2];
}

/* F and T added onto the engine's row rk (and F onto its stored-force row). */
RS_INLINE void rs_load_onto_row(const rs_load_rows *rows, int rk, const double F[3],
                                const double T[3])
{
    double *fi = rows->f + 3 * (size_t)rk, *ti = rows->t + 3 * (size_t)rk;
    fi[0] += F[0], fi[1] += F[1], fi[2] += F[2];
    ti[0] += T[0], ti[1] += T[1], ti[2] += T[2];
    if (rows->fstore) {
        double *si = rows->fstore + 3 * (size_t)rk;
        si[0] += F[0], si[1] += F[1], si[2] += F[2];
    }
}

#endif
