/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * spacetime.h - the explorer's space-time view (V): each body's position
 * against t, one line per body, and the contacts of each interface.
 *
 * The arc keeps the interval's interface only (x, x_c, F_c of one pair),
 * not every body's position, and a chain's run cannot be seeked back.  So
 * while the view is on, spacetime.c runs a second sim of the current
 * scene (the "shadow") a step at a time within the frame's budget and
 * records, in its own bounded buffer, every body's position and velocity
 * (hb_sim_body) on a time grid and at every jump, and each contact's
 * interface and extent: the interface in contact is the one whose gap
 * (from the bodies' positions and half-lengths) is the arc sample's x.
 * Between records a body's path is the cubic through both ends' positions
 * and velocities, which is its parabola in free flight.  The buffer holds
 * ST_MAX_VALUES positions (16384 records at most, 256 at least; the grid
 * starts at T over half of them): when full, every other record goes and
 * the grid doubles; contacts are kept up to ST_MAX_CONTACTS.
 *
 * pane_spacetime.c draws it over the plots' rectangle.
 */
#ifndef HYBOUNCE_SPACETIME_H
#define HYBOUNCE_SPACETIME_H

#include <stddef.h>

enum { ST_MAX_VALUES = 1 << 20, ST_MAX_CONTACTS = 1 << 16 };

struct app;
struct canvas;
struct hb_sim;

/* One contact of one interface: k as docs/chains.md numbers them (0: the floor's). */
struct st_contact {
	int k;
	long j;              /* its flow interval in the shadow's arc */
	double t0, t1;       /* its extent, s (t1: the last sample seen while it lasts) */
};

struct spacetime {
	int on;
	int iface;                  /* the interface the plots show, + 1 (0: the run's own, as recorded) */
	int body;                   /* or the body whose y and u they show, + 1 (0: none; not with iface) */
	const struct hb_sim *src;   /* the explorer's run this one shadows */
	struct hb_sim *sh;          /* the shadow (NULL: none) */
	unsigned char *scene;       /* the scene it was built from (bytes, to see an edit) */
	size_t scene_size;
	int nb, k0;                 /* bodies; first interface (0 with a floor) */
	double *R;                  /* nb half-lengths, m */
	double floor_y;             /* the floor's surface, m */
	/* records: t[i], and y, u of body b at y[i * nb + b], u[...] */
	size_t nrec, cap;
	double *t, *y, *u;
	double dt;                  /* the grid: a record at least this far after the last */
	double ylo, yhi;            /* the range of every position recorded, m */
	double T;                   /* the run's horizon */
	long last_j;                /* j of the shadow's interval at the last step */
	struct st_contact *c;
	size_t nc, ccap;
	long lost;                  /* contacts past ST_MAX_CONTACTS, not kept */
	int failed;                 /* the shadow could not be built (no memory): view empty */
	/* pane_spacetime.c: last frame's canvas, drawn again while nothing it shows changed */
	struct canvas *cv;
	struct { size_t nrec, nc; double t0, t1, t_last, c_last; int w, h, braille; } cv_key;
};

/* V: the view on / off (spacetime.c). */
void act_spacetime(struct app *a);
/* 1 when the view replaces the plots. */
int spacetime_on(const struct app *a);
/* K: the interface whose x, x_c and F_c the plots show: the next one, then the run's own. */
void act_iface(struct app *a);
/* That interface k (docs/chains.md numbering), or -1: the run's own (each interval's). */
int spacetime_iface(const struct app *a);
/* B: the body whose position and velocity the plots show: the next one, then the run's own. */
void act_body(struct app *a);
/* That body b (0-based, 0 the lowest), or -1: none. */
int spacetime_body(const struct app *a);
/* " k=K" (" b=B", 1-based) for the status line while an interface (a body) is chosen, else "".  Returns buf. */
char *spacetime_state(const struct app *a, char *buf, size_t n);
/* The gap of interface k at t (the records' cubic), m. */
double st_gap_at(const struct spacetime *st, int k, double t);
/* One frame's work on the shadow (within the frame's budget); 1 while computing. */
int spacetime_tick(struct app *a);
void spacetime_free(struct app *a);

/*
 * Body b's position at t by the record's cubic (t within the records);
 * *i is a hint, the record interval last used (start at 0).
 */
double st_y_at(const struct spacetime *st, int b, double t, size_t *i);
/* Body b's velocity at t: the derivative of that cubic. */
double st_u_at(const struct spacetime *st, int b, double t, size_t *i);
/* The gap of interface k at record i, m. */
double st_gap(const struct spacetime *st, int k, size_t i);

/* pane_spacetime.c: draws the view into the plots' rectangle. */
void pane_spacetime_draw(const struct app *a);
/* ... its canvas copy and its y labels, shared with pane_iface.c */
void st_blit(const struct app *a, const struct canvas *c, int y, int x, int curcol);
struct axis;
void st_ylabels(const struct axis *ay, int y, int h, const char *name);
/* The time axis: the plots' in the follow and zoom views, else the whole run. */
void st_time_range(const struct app *a, const struct spacetime *st, double *t0, double *t1);
/*
 * pane_stack.c: a pane of nq plots against t stacked over the plots' time
 * axis.  range sets [*lo, *hi] of plot q over [t0, t1] (pw pixel columns),
 * draw draws it; ctx is theirs; key is the key that leaves the pane.
 */
enum { STACK_MAXQ = 4 };
struct stack_plots {
	int nq;
	const char *name[STACK_MAXQ], *unit[STACK_MAXQ];
	int key;
	const void *ctx;
	void (*range)(const struct spacetime *st, const void *ctx, int q, double t0, double t1,
	              int pw, double *lo, double *hi);
	void (*draw)(const struct spacetime *st, const void *ctx, struct canvas *c, int q, double t0,
	             double t1);
};
/* Draws the pane under title (a buffer of tn bytes, added to: computing, ...). */
void pane_stack_draw(const struct app *a, char *title, size_t tn, const struct stack_plots *sp);
/* A value of who (a body, an interface) at t from the records; *hint as st_y_at's. */
typedef double st_fn(const struct spacetime *st, int who, int q, double t, size_t *hint);
/* Widens [*lo, *hi] to fn's finite values at the pixel columns of [t0, t1] within the records. */
void st_fn_widen(const struct spacetime *st, st_fn *fn, int who, int q, double t0, double t1,
                 int pw, double *lo, double *hi);
/* Draws fn through the pixel columns of [t0, t1] within the records. */
void st_fn_draw(const struct spacetime *st, struct canvas *c, st_fn *fn, int who, int q, double t0,
                double t1);
/* pane_iface.c: x, x_c and F_c of the chosen interface, in the plots' rectangle. */
void pane_iface_draw(const struct app *a);
/* pane_body.c: y and u of the chosen body, in the plots' rectangle. */
void pane_body_draw(const struct app *a);

#endif
