/* Walls made from the words of `fix wall/rigid` lines, over particles whose states a DEM
 * code gives each step: here read from a LIGGGHTS dump, so that a code's coupling can be
 * checked against the fix itself (docs/coupling.md).
 *
 *   walls SCENE DUMP [--hold K]
 *
 * SCENE holds `dt DT`, `skin S`, `box XLO XHI YLO YHI ZLO ZHI` and one line per wall,
 * `wall ID WORDS...`, the words after `fix ID group wall/rigid`. DUMP is a LIGGGHTS custom
 * dump sorted by id with the columns id x y z vx vy vz omegax omegay omegaz radius mass:
 * each frame is one step, the first a setup call (the forces before the first step). Per
 * step and wall the program prints each particle's force from that wall ("step S wall ID
 * id fx fy fz"). A step is, per wall, at most rs_wall_advance (a moving wall) and
 * rs_wall_step; rs_wall_reneighbor only when a particle has moved half a skin since the
 * candidates were found, as an engine rebuilds its neighbour lists. --hold K: the first
 * frame's particles held K steps, the walls' time per particle-step printed. */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include <rigidsurf/wall.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

enum { MAXWALL = 8, MAXWORDS = 256 };

typedef struct wall {
    char id[64];
    char *words[MAXWORDS];
    int nwords;
    rs_wall *w;
} wall;

typedef struct particles {
    int n;
    long long step;
    double *x, *v, *omega, *radius, *mass, *f, *t;
    int *id;
} particles;

static int die(const char *what, const char *msg)
{
    fprintf(stderr, "walls: %s: %s\n", what, msg);
    return 1;
}

/* The scene: the run's settings and the walls' words. */
static int read_scene(const char *path, rs_wall_run *run, wall *walls, int *nwall)
{
    FILE *fp = fopen(path, "r");
    if (!fp)
        return die(path, "cannot open");
    char line[4096];
    int lineno = 0;
    while (fgets(line, sizeof line, fp)) {
        lineno++;
        char *tok[MAXWORDS], *save = NULL;
        int nt = 0;
        for (char *s = strtok_r(line, " \t\r\n", &save); s && nt < MAXWORDS;
             s = strtok_r(NULL, " \t\r\n", &save))
            tok[nt++] = s;
        if (nt == 0 || tok[0][0] == '#')
            continue;
        if (strcmp(tok[0], "dt") == 0 && nt == 2) {
            run->dt = atof(tok[1]);
        } else if (strcmp(tok[0], "skin") == 0 && nt == 2) {
            run->skin = atof(tok[1]);
        } else if (strcmp(tok[0], "box") == 0 && nt == 7) {
            for (int d = 0; d < 3; d++)
                run->box_lo[d] = atof(tok[1 + 2 * d]),
                run->box_hi[d] = atof(tok[2 + 2 * d]);
        } else if (strcmp(tok[0], "wall") == 0 && nt >= 3 && *nwall < MAXWALL) {
            wall *wl = &walls[(*nwall)++];
            snprintf(wl->id, sizeof wl->id, "%s", tok[1]);
            for (int k = 2; k < nt; k++)
                wl->words[wl->nwords++] = strdup(tok[k]);
        } else {
            fprintf(stderr, "walls: %s:%d: expected dt, skin, box or wall ID WORDS...\n",
                    path, lineno);
            fclose(fp);
            return 1;
        }
    }
    fclose(fp);
    return 0;
}

/* The next frame of the dump into p (allocated on the first); 0 at its end. */
static int read_frame(FILE *fp, particles *p)
{
    char line[1024];
    long long step;
    int n;
    if (!fgets(line, sizeof line, fp) || !fgets(line, sizeof line, fp) ||
        sscanf(line, "%lld", &step) != 1)
        return 0;
    if (!fgets(line, sizeof line, fp) || !fgets(line, sizeof line, fp) ||
        sscanf(line, "%d", &n) != 1)
        return 0;
    for (int k = 0; k < 5; k++) /* the box, and the columns' header */
        if (!fgets(line, sizeof line, fp))
            return 0;
    if (!p->x) {
        p->n = n;
        p->x = calloc(3 * (size_t)n, sizeof(double));
        p->v = calloc(3 * (size_t)n, sizeof(double));
        p->omega = calloc(3 * (size_t)n, sizeof(double));
        p->f = calloc(3 * (size_t)n, sizeof(double));
        p->t = calloc(3 * (size_t)n, sizeof(double));
        p->radius = calloc((size_t)n, sizeof(double));
        p->mass = calloc((size_t)n, sizeof(double));
        p->id = calloc((size_t)n, sizeof(int));
    }
    if (n != p->n)
        return 0;
    p->step = step;
    for (int i = 0; i < n; i++) {
        double *x = p->x + 3 * i, *v = p->v + 3 * i, *w = p->omega + 3 * i;
        if (fscanf(fp, "%d %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf", &p->id[i], &x[0],
                   &x[1], &x[2], &v[0], &v[1], &v[2], &w[0], &w[1], &w[2], &p->radius[i],
                   &p->mass[i]) != 12 ||
            !fgets(line, sizeof line, fp)) /* the row's further columns */
            return 0;
    }
    return 1;
}

static rs_wall_block block_of(const particles *p, int inc, double t0, int setup, double dt)
{
    rs_wall_block b;
    memset(&b, 0, sizeof b);
    b.n = p->n;
    b.x = p->x, b.v = p->v, b.omega = p->omega;
    b.radius = p->radius, b.mass = p->mass, b.id = p->id;
    b.step = p->step;
    b.inc = inc;
    b.time = setup ? t0 : t0 + (inc - 1) * dt;
    return b;
}

/* The walls' forces on the particles at one step, printed. */
static int print_forces(const particles *p, const wall *wl)
{
    for (int i = 0; i < p->n; i++) {
        const double *f = p->f + 3 * i;
        printf("step %lld wall %s id %d %.17g %.17g %.17g\n", p->step, wl->id, p->id[i],
               f[0], f[1], f[2]);
    }
    return 0;
}

/* The largest displacement since the candidates were found: past half a skin, they are
 * found again (the engine's rebuild). */
static double moved(const particles *p, const double *x0)
{
    double m2 = 0.0;
    for (int k = 0; k < 3 * p->n; k += 3) {
        const double dx = p->x[k] - x0[k], dy = p->x[k + 1] - x0[k + 1],
                     dz = p->x[k + 2] - x0[k + 2];
        m2 = fmax(m2, dx * dx + dy * dy + dz * dz);
    }
    return sqrt(m2);
}

int main(int argc, char **argv)
{
    if (argc != 3 && !(argc == 5 && strcmp(argv[3], "--hold") == 0))
        return die("usage", "walls SCENE DUMP [--hold K]");
    rs_wall_run run;
    memset(&run, 0, sizeof run);
    wall walls[MAXWALL];
    memset(walls, 0, sizeof walls);
    int nwall = 0;
    if (read_scene(argv[1], &run, walls, &nwall))
        return 1;
    FILE *fp = fopen(argv[2], "r");
    if (!fp)
        return die(argv[2], "cannot open");
    particles p;
    memset(&p, 0, sizeof p);
    if (!read_frame(fp, &p))
        return die(argv[2], "no frame");
    const int hold = argc == 5 ? atoi(argv[4]) : 0;

    /* The walls, made from their words, one rank and no engine behind them. */
    rs_error err;
    rs_wall_host host;
    memset(&host, 0, sizeof host);
    rs_wall_rows rows;
    memset(&rows, 0, sizeof rows);
    rows.f = p.f, rows.torque = p.t;
    const double t0 = 0.0;
    for (int k = 0; k < nwall; k++) {
        wall *wl = &walls[k];
        rs_wall_block b = block_of(&p, 1, t0, 1, run.dt);
        if (rs_wall_create(wl->id, "all", (const char *const *)wl->words, wl->nwords, &host,
                           &wl->w, &err) != RS_OK ||
            rs_wall_grow(wl->w, p.n, &err) != RS_OK ||
            rs_wall_init(wl->w, &run, &b, &err) != RS_OK)
            return die(wl->id, err.msg);
        memset(p.f, 0, 3 * (size_t)p.n * sizeof(double));
        if (rs_wall_setup(wl->w, &b, &rows, NULL, &err) != RS_OK)
            return die(wl->id, err.msg);
        if (!hold)
            print_forces(&p, wl);
    }
    double *x0 = malloc(3 * (size_t)p.n * sizeof *x0);
    memcpy(x0, p.x, 3 * (size_t)p.n * sizeof *x0);
    struct timespec a, z;
    clock_gettime(CLOCK_MONOTONIC, &a);
    for (int inc = 1; hold ? inc <= hold : read_frame(fp, &p); inc++) {
        const int rebuild = moved(&p, x0) > 0.5 * run.skin;
        if (rebuild)
            memcpy(x0, p.x, 3 * (size_t)p.n * sizeof *x0);
        const rs_wall_block b = block_of(&p, inc, t0, 0, run.dt);
        for (int k = 0; k < nwall; k++) {
            rs_wall *w = walls[k].w;
            if (rebuild)
                rs_wall_reneighbor(w);
            memset(p.f, 0, 3 * (size_t)p.n * sizeof(double));
            if ((rs_wall_get_info(w)->moving &&
                 rs_wall_advance(w, run.dt, &err) != RS_OK) ||
                rs_wall_step(w, &b, &rows, run.dt, NULL, &err) != RS_OK)
                return die(walls[k].id, err.msg);
            if (!hold)
                print_forces(&p, &walls[k]);
        }
    }
    clock_gettime(CLOCK_MONOTONIC, &z);
    if (hold)
        printf("walls: %d particles, %d steps, %.4f ns per particle-step\n", p.n, hold,
               ((z.tv_sec - a.tv_sec) * 1e9 + (z.tv_nsec - a.tv_nsec)) /
                   ((double)p.n * hold));
    for (int k = 0; k < nwall; k++) {
        rs_wall_free(walls[k].w);
        for (int j = 0; j < walls[k].nwords; j++)
            free(walls[k].words[j]);
    }
    free(x0);
    free(p.x), free(p.v), free(p.omega), free(p.f), free(p.t), free(p.radius), free(p.mass);
    free(p.id);
    fclose(fp);
    return 0;
}
