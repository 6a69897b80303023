/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim.c - the simulator of the hybrid systems H_r and H_f (paper section
 * Model, eqs. Hr_f .. Hr_init and H_f .. H_init).
 *
 * State and sets, exactly as the paper:
 *     C = {q_c = 0, (x >= 0 or v >= 0)} u {q_c = 1, (Phi <= 0 or v <= 0)}
 *     D = {q_c = 0, x <= 0, v <= 0}     u {q_c = 1, Phi >= 0, v >= 0}
 *     g: x, v, x_m, v_m unchanged; x_c = 0, z_c = 0, q_c = 1 - q_c.
 * Continuous indicators of C: I = max(x, v) in flight and I = -min(Phi, v)
 * in contact; the state is in C while I >= 0, and only a strictly negative
 * I leaves C (rule R2: a state on the boundary keeps flowing).
 *
 * Work is organised by flow interval (DESIGN.md section 3):
 *  - flight, F_er constant on [t, T]: closed form x + v tau + a tau^2 / 2,
 *    the event from the quadratic, then nudged by ulps into D;
 *  - flight otherwise: GSL on (x, v) (+ (x_m, v_m) when HB_REDUCE_COM is off);
 *  - contact: GSL on (x_c, v, z_c, W, J_Fc, J_Fe) with x = x_e + x_c
 *    (or with x as well when HB_REDUCE_CONTACT is off).
 * The ODE is integrated in scaled variables u_i = y_i / s_i, with s_i the
 * component's scale taken from the interval's own sizes (see scales()), so
 * that GSL's standard control with one eps_abs = atol gives each component
 * the absolute tolerance atol * s_i.
 *
 * After every accepted step the indicator, the law's switching functions
 * and the extremum functions (v for x_c^max, dPhi/dt for F_c^max) are
 * compared with their values at the step's start.  A change of sign is
 * located with GSL's Brent solver, the earliest of several crossings
 * first: on the step's continuous extension (dop853) or its cubic Hermite
 * interpolant (the other steppers), then on re-steps from the step's start
 * (one step of the same method of length h, h in the bracket) about the
 * point found, down to a few ulps of t (sim_locate.c).  An event ends the
 * interval at the bracket's end in D; a switching or extremum crossing
 * ends the step at the bracket's far end and restarts the stepper
 * (DESIGN.md section 4a); the law's mode term keeps its sign through a
 * step (kinks as modes).  Load kinks (T_e, T_s) are step targets.  An
 * event inside a step whose two ends are in C is looked for by a cubic
 * Hermite test of the indicator (dip()).
 *
 * Scales are powers of 2 (exact scaling); GSL's standard control is used
 * without growth right after a rejection (control.c); bsimp runs on
 * shifted variables (step_bsimp.c).  Every 32nd step of an explicit
 * stepper in contact checks the stiffness of the flow (stiffness()):
 * run.stepper = auto then goes over to bsimp for the contacts.
 *
 * What is per interface is written once for this driver and a chain's
 * clusters' (sim_cluster_step.c; docs/chains.md section 8a): the watched
 * terms and the mode of a step (sim_iface.h), the noise filter of a
 * crossing (hbs_candidate), a contact's scales (hbs_contact_scale), the
 * stepper and one accepted step of the evolver (sim_flow.c), and the
 * stiffness check (sim_stiff.c).
 *
 * The state is that of a chain (docs/chains.md, sim_chain.c): bodies and
 * the interfaces between them, each interface with its own law, effective
 * mass and state (q_c, x, v, x_c, z, W, J_Fc, J_Fe, extrema, commencement
 * values); s->I is the interface the current flow interval integrates,
 * and (x_m, v_m) the centre of mass of its pair.  Today's scenes are the
 * chains of one interface: two bodies (H_f) or one on the floor (H_r).
 *
 * Invariants: the arc's samples are all in C except each pre-jump sample,
 * which is in D by hb_check_in_D's test; post-jump samples are g of the
 * pre-jump ones bit for bit; a failed step leaves the arc as it was.
 */
#include "sim_impl.h"
#include "sim_iface.h"
#include "clock.h"
#include "cnum.h"

/*
 * A flow interval continued after hb_sim_seek (or hb_sim_set_scene) from inside
 * it: what a run that had not stopped would carry on with.  The scales are
 * those of the interval's first sample (a fresh run took them there), and
 * the noise filter's largest values (gmax, vmax) are those of the samples
 * kept, so that round-off-level kink crossings are ignored as they were
 * before the seek (without them every step "locates" one).
 */
static void
resume_interval(struct hb_sim *s)
{
	struct iface *I = s->I;
	const struct layout *L = &s->cur->L;
	const struct hb_arc_sample *f = hb_arc_at(s->arc, s->resume_first);
	double t = s->t, x = I->x, v = I->v, xm = s->xm, vm = s->vm;
	double fv[MAXFUN], u[MAXDIM];
	int kind[MAXFUN], n, i;
	size_t k;

	s->t = f->t;
	I->x = f->x;
	I->v = f->v;
	s->xm = f->xm;
	s->vm = f->vm;
	hbs_scales(s, L, I->q);
	s->t = t;
	I->x = x;
	I->v = v;
	s->xm = xm;
	s->vm = vm;
	for (k = s->resume_first; k <= s->resume_last; k++) {
		const struct hb_arc_sample *a = hb_arc_at(s->arc, k);

		hbs_pack_sample(s, L, a, u);
		n = hbs_watch(s, s->cur, a->t, u, fv, kind);
		for (i = 0; i < n; i++)
			s->gmax[i] = fmax(s->gmax[i], fabs(fv[i]));
		s->vmax = fmax(s->vmax, fabs(a->v));
	}
}

/* Begins a flow interval at the current state. */
static int
setup_interval(struct hb_sim *s)
{
	struct iface *I = s->I;
	const struct hb_scene *sc = &s->sc;

	s->setup = 0;
	s->ntiny = 0;
	s->msign = s->mforce = 0;
	memset(s->gmax, 0, sizeof s->gmax);
	s->vmax = fabs(I->v);
	s->closed = !I->q && (s->chain || ((sc->run.reduce & HB_REDUCE_FLIGHT) &&
	            hb_scene_Fer_constant(sc, s->t, sc->run.T) &&
	            (sc->d.system == HB_SCENE_REDUCED || (sc->run.reduce & HB_REDUCE_COM))));
	if (s->closed) {
		s->resume = 0;
		return 0;
	}
	s->stiff_row = 0;
	if (s->built[I->q] != s->stepper[I->q] && hbs_phase_alloc(s, &s->ph[I->q], I->q))
		return hbs_fail(s, HB_ENOMEM, "out of memory for the integrator");
	s->cur = &s->ph[I->q];
	if (s->resume)
		resume_interval(s);
	else
		hbs_scales(s, &s->cur->L, I->q);
	hbs_pack(s, &s->cur->L, s->u);
	gsl_odeiv2_driver_reset(s->cur->d);
	{
		double Tc = I->q ? s->scale[s->cur->L.ixc] / s->scale[s->cur->L.iv]
		                 : s->scale[s->cur->L.ix] / s->scale[s->cur->L.iv];
		s->Tc = Tc;
		/*
		 * The first step: the one the last interval of this kind began with
		 * (in units of its Tc), else 1e-2 Tc.  A contact's first steps are
		 * short (Phi grows as x_c^p from x_c = 0, not smoothly), and the
		 * guess 1e-2 Tc was rejected about seven times at each contact.
		 */
		s->h = s->h1[I->q] > 0 ? s->h1[I->q] * Tc : 1e-2 * Tc;
		s->h = fmin(s->h, sc->run.T - s->t);
		s->first = 1;
		if (s->resume && s->resume_h > 0)
			s->h = fmin(s->resume_h, sc->run.T - s->t);
		if (!(s->h > 0))
			s->h = 1e-9;
	}
	s->resume = 0;
	return 0;
}

/*
 * Kinks as modes: the sign of the law's |w| term (law_type.psi_mode) is
 * frozen for the step that begins at the current state, so that the flow
 * is smooth inside it; its value is the sign of the switching function
 * there, or the side a crossing located at this instant went over to.
 * When it changes, the stepper forgets its stored derivative (first same
 * as last), which was of the other mode.
 */
static void
set_mode(struct hb_sim *s)
{
	const struct iface *I = s->I;
	const struct phase *p = s->cur;
	int m = 0;

	if (p->q && s->mforce && s->mforce_t == s->t) {
		m = s->mforce;
	} else if (p->q) {
		/* unscaled as hbs_unscale does, only the components read */
		double z[HB_LAW_MAX_Z] = { 0 };
		const struct layout *L = &p->L;
		const double *u = s->u0, *sc_ = s->scale;
		int i;

		for (i = 0; i < I->law->n_z; i++)
			z[i] = u[L->iz + i] * sc_[L->iz + i];
		m = hbs_iface_mode(s, I, u[L->ixc] * sc_[L->ixc], z, u[L->iv] * sc_[L->iv]);
	}
	if (m != s->msign) {
		s->msign = m;
		gsl_odeiv2_driver_reset(s->cur->d);
	}
}

/* One accepted step of the numeric phase, with what follows from it. */
static int
numeric_step(struct hb_sim *s)
{
	struct phase *p = s->cur;
	const struct hb_scene *sc = &s->sc;
	double t = s->t, t1 = sc->run.T, kinks[4];
	int nk, load_kink = 0, rc;

	/* a state already outside C where the interval begins jumps at once (rule R2) */
	{
		double f0 = hbs_watch_indicator(s, p, s->t, s->u);

		if (f0 < 0.0)
			return hbs_jump(s, HB_LOCATE_START, 0, 0.0, f0, f0);
	}
	nk = sc->run.kinks ? hb_scene_load_kinks(sc, t, t1, kinks, 4) : 0;
	if (nk > 0) {
		t1 = kinks[0];
		load_kink = 1;
	}
	if (p->q && sc->run.h_max > 0 && t + sc->run.h_max < t1) {
		t1 = t + sc->run.h_max;
		load_kink = 0;
	}
	memcpy(s->u0, s->u, sizeof s->u);
	s->t0 = t;
	s->hug = hbs_hugging(s, s->u0);
	set_mode(s);
	if ((rc = hbs_evolve(s, p->d->e, p->d->c, p->d->s, &p->sys, s->t0, s->u0, t1, &t, &s->h, s->u,
	                     &s->H)))
		return rc;
	if (s->first && t < t1) /* the step this interval's start took, in units of Tc */
		s->h1[p->q] = s->H / s->Tc;
	s->first = 0;
	{
		double dt0, dh;

		/* on Phi = 0 to the noise, the interpolant's error would exceed the noise: re-step */
		s->use_dense = !s->hug && hb_dop853_last(p->d->s, &dt0, &dh) == 0 && dt0 == s->t0;
	}
	memcpy(s->u1, s->u, sizeof s->u);
	if ((rc = hbs_after_step(s, load_kink && t == t1)))
		return rc;
	if (s->end == HB_SIM_RUNNING && !s->setup && (rc = hbs_stiffness(s)))
		return rc;
	if (s->end == HB_SIM_RUNNING && !s->setup && s->t >= sc->run.T) {
		/* the horizon: the last sample is the end */
		if ((rc = hbs_push_sample(s, HB_ARC_END)))
			return rc;
		hbs_finish_T(s);
	}
	return 0;
}

static void
reset_state(struct hb_sim *s)
{
	struct iface *I = s->I;
	const struct hb_scene *sc = &s->sc;

	s->end = HB_SIM_RUNNING;
	s->err[0] = s->endmsg[0] = '\0';
	s->t = 0.0;
	s->j = 0;
	I->q = 0;
	I->x = sc->init.x0;
	I->v = sc->init.v0;
	I->xc = 0.0;
	memset(I->z, 0, sizeof I->z);
	s->xm = sc->d.system == HB_SCENE_FULL ? sc->init.xm0 : 0.0;
	s->vm = sc->d.system == HB_SCENE_FULL ? sc->init.vm0 : 0.0;
	I->W = I->JFc = I->JFe = I->xcmax = I->Fcmax = 0.0;
	I->Ee = I->Wc = I->Wc0 = 0.0;
	I->xe = I->te = I->vi = 0.0;
	if (s->chain) {
		hbs_chain_reset(s);
	}
	for (int k = 0; k < s->nif; k++)
		s->ifc[k].ninst = 0;
	s->setup = 1;
	s->resume = 0;
	s->h1[0] = s->h1[1] = 0.0;
	s->ncol = 0;
	s->ncol_total = 0;
	s->stepper[1] = sc->run.stepper == HB_STEPPER_AUTO ? HB_STEPPER_RK8PD : sc->run.stepper;
	hbs_pend_drop(s);
	arc_truncate(s->arc, 0);
	{
		struct hb_sim_stats keep = s->st;

		memset(&s->st, 0, sizeof s->st);
		s->st.ncomp = keep.ncomp;
		memcpy(s->st.comp, keep.comp, sizeof s->st.comp);
	}
	s->unit_n = 0;
	hbs_push_sample(s, HB_ARC_START);
	hbs_branches_clear(s);
}

void
hbs_reset_state(struct hb_sim *s)
{
	reset_state(s);
}

static int
build(struct hb_sim *s, char *msg, size_t n)
{
	int q;

	if ((q = hbs_chain_bind(s)) != 0)
		return q == HB_ENOMEM ? hb_status_set(msg, n, HB_ENOMEM, "out of memory for the chain")
		                      : hb_status_set(msg, n, q, "the chain's scene names a body or "
		                                      "interface it does not have");
	if (s->chain && !hbs_chain_stepper_ok(s->sc.run.stepper))
		return hb_status_set(msg, n, HB_EINVAL, "run.stepper: a chain's contacts run with rk8pd, "
		                     "dop853, vern98, rkf45, rkck, bsimp or auto (rk8pd, then bsimp once "
		                     "stiff); accepted: those");
	for (q = 0; q < 2; q++)
		s->stepper[q] = s->sc.run.stepper == HB_STEPPER_AUTO ? HB_STEPPER_RK8PD : s->sc.run.stepper;
	for (q = 0; q < 2; q++)
		if (hbs_phase_alloc(s, &s->ph[q], q))
			return hb_status_set(msg, n, HB_ENOMEM, "out of memory for the integrator");
	{
		const char *names[MAXDIM];
		const struct layout *L = &s->ph[1].L;
		int i;

		for (i = 0; i < MAXDIM; i++)
			names[i] = "";
		if (L->ix >= 0) names[L->ix] = "x";
		names[L->ixc] = "x_c";
		names[L->iv] = "v";
		for (i = 0; i < s->I->law->n_z; i++)
			names[L->iz + i] = i ? "z_c2" : (s->I->law->n_z > 1 ? "z_c1" : "z_c");
		names[L->iW] = "W";
		names[L->iJc] = "J_Fc";
		names[L->iJe] = "J_Fe";
		names[L->iEe] = "E_e";
		if (L->ixm >= 0) {
			names[L->ixm] = "x_m";
			names[L->ivm] = "v_m";
		}
		/* the names depend on the law only through n_z: keep per-sim copies */
		for (i = 0; i < HB_SIM_MAXCOMP; i++)
			s->st.comp[i] = i < L->dim ? names[i] : NULL;
	}
	return 0;
}

struct hb_sim *
hb_sim_new(const struct hb_scene *sc, char *msg, size_t n)
{
	struct hb_sim *s;

	s = calloc(1, sizeof *s);
	if (s == NULL) {
		hb_status_set(msg, n, HB_ENOMEM, "out of memory");
		return NULL;
	}
	s->sc = *sc;
	if (hb_scene_validate(&s->sc, msg, n) != 0) {
		free(s);
		return NULL;
	}
	s->arc = arc_new((size_t)s->sc.run.max_samples);
	s->root = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
	if (s->arc == NULL || s->root == NULL || build(s, msg, n) != 0) {
		if (s->arc == NULL || s->root == NULL)
			hb_status_set(msg, n, HB_ENOMEM, "out of memory");
		hb_sim_free(s);
		return NULL;
	}
	reset_state(s);
	return s;
}

void
hb_sim_free(struct hb_sim *s)
{
	if (s == NULL)
		return;
	hbs_phase_free(&s->ph[0]);
	hbs_phase_free(&s->ph[1]);
	if (s->root)
		gsl_root_fsolver_free(s->root);
	if (s->eig)
		gsl_eigen_nonsymm_free(s->eig);
	if (s->Jdyn)
		gsl_matrix_free(s->Jdyn);
	if (s->lambda)
		gsl_vector_complex_free(s->lambda);
	arc_free(s->arc);
	hbs_chain_free(s);
	hbs_cluster_free(s);
	free(s->br);
	free(s->col);
	free(s->pend.s);
	free(s);
}

int
hb_sim_advance(struct hb_sim *s, long max_steps, double max_seconds)
{
	double start = clock_seconds(CLOCK_MONOTONIC), cpu0 = clock_seconds(CLOCK_PROCESS_CPUTIME_ID);
	long work0 = s->work;
	int rc = 0;

	if (s->pend.active) { /* a chain's seek kept the rest of a unit's outputs aside: first those */
		if ((rc = hbs_pend_flush(s)) != 0 || s->end != HB_SIM_RUNNING)
			return rc;
	}
	if (s->end != HB_SIM_RUNNING)
		return HB_EDONE;
	while (s->end == HB_SIM_RUNNING) {
		if (max_steps > 0 && s->work - work0 >= max_steps)
			break;
		if (max_seconds > 0 && ((s->work - work0) & 7) == 0 &&
		    clock_seconds(CLOCK_MONOTONIC) - start >= max_seconds)
			break;
		s->unit_n = 0;
		if (s->chain) { /* a chain: its flights and its clusters of contacts (sim_cluster.c) */
			if (s->setup && (rc = hbs_cluster_setup(s)))
				break;
			s->work++;
			rc = s->cx.nact ? hbs_cluster_step(s) : hbs_chain_flight(s);
			if (rc)
				break;
			continue;
		}
		if (s->setup) {
			if ((rc = setup_interval(s)))
				break;
		}
		s->work++;
		if (s->closed)
			rc = hbs_flight_closed(s);
		else
			rc = numeric_step(s);
		if (rc)
			break;
	}
	s->st.seconds += clock_seconds(CLOCK_PROCESS_CPUTIME_ID) - cpu0;
	s->st.wall += clock_seconds(CLOCK_MONOTONIC) - start;
	return rc;
}

int
hb_sim_run(struct hb_sim *s)
{
	return hb_sim_advance(s, 0, 0.0);
}

enum hb_sim_end
hb_sim_end(const struct hb_sim *s)
{
	return s->end;
}

const char *
hb_sim_end_str(const struct hb_sim *s)
{
	return s->end == HB_SIM_RUNNING ? "running" : s->endmsg;
}

const char *
hb_sim_errmsg(const struct hb_sim *s)
{
	return s->err;
}

const struct hb_scene *
hb_sim_scene(const struct hb_sim *s)
{
	return &s->sc;
}

const struct hb_arc *
hb_sim_arc(const struct hb_sim *s)
{
	return s->arc;
}

const struct hb_sim_stats *
hb_sim_stats(const struct hb_sim *s)
{
	return &s->st;
}

size_t
hb_sim_ncollisions(const struct hb_sim *s)
{
	return s->ncol;
}

long
hb_sim_collisions_total(const struct hb_sim *s)
{
	return s->ncol_total;
}

const struct hb_collision *
hb_sim_collision(const struct hb_sim *s, size_t i)
{
	return i < s->ncol ? &s->col[i] : NULL;
}

int
hb_sim_contact_live(const struct hb_sim *s, struct hb_collision *out)
{
	const struct iface *I = s->I;
	if (!I->q || s->pend.active) /* (after a chain's seek, the state is the unit's end: none) */
		return 0;
	memset(out, 0, sizeof *out);
	out->i = s->ncol_total;
	out->j = s->j;
	out->te = I->te;
	out->ts = s->t;
	out->td = s->t - I->te;
	out->tf = NAN;
	out->vi = I->vi;
	out->e = I->vi != 0.0 ? -I->v / I->vi : NAN;
	out->xcmax = I->xcmax;
	out->Fcmax = I->Fcmax;
	out->xcr = fabs(I->xc);
	out->xcr_sum = (s->ncol > 0 ? s->col[s->ncol - 1].xcr_sum : 0.0) + out->xcr;
	out->W = I->W;
	out->JFc = I->JFc;
	out->JFe = I->JFe;
	out->Lambda = I->JFc != 0.0 ? I->JFe / I->JFc : NAN;
	out->complete = 0;
	out->k = s->k0 + s->ia;
	return 1;
}

int
hb_sim_seek(struct hb_sim *s, size_t i)
{
	struct iface *I = s->I;
	const struct hb_arc_sample *a;
	const struct hb_arc_interval *iv;

	if (s->chain) /* replayed to the sample (sim_seek.c) */
		return hbs_chain_seek(s, i);
	if (i >= hb_arc_len(s->arc))
		return HB_EINVAL;
	hbs_branches_cut(s, i);
	/*
	 * The step to continue with: the one the controller proposes where the
	 * simulator stands at that sample (an edit at the run's end, a seek
	 * to it), else the one the run took from that sample.
	 */
	s->resume_h = 0.0;
	if (i + 1 < hb_arc_len(s->arc) && hb_arc_at(s->arc, i + 1)->j == hb_arc_at(s->arc, i)->j)
		s->resume_h = hb_arc_at(s->arc, i + 1)->t - hb_arc_at(s->arc, i)->t;
	else if (i + 1 == hb_arc_len(s->arc) && s->end == HB_SIM_RUNNING && !s->setup
	         && s->t == hb_arc_at(s->arc, i)->t && s->j == hb_arc_at(s->arc, i)->j && s->h > 0)
		s->resume_h = s->h;
	arc_truncate(s->arc, i + 1);
	a = hb_arc_at(s->arc, i);
	iv = hb_arc_interval_at(s->arc, hb_arc_interval_of(s->arc, i));
	/* continuing inside the interval (not at its pre-jump end) */
	s->resume = a->kind != HB_ARC_PRE_JUMP;
	s->resume_first = iv->first;
	s->resume_last = i;
	s->t = a->t;
	s->j = a->j;
	I->q = a->q;
	I->x = a->x;
	I->v = a->v;
	I->xc = a->xc;
	memcpy(I->z, a->z, sizeof I->z);
	s->xm = a->xm;
	s->vm = a->vm;
	I->W = a->W;
	I->JFc = a->JFc;
	I->JFe = a->JFe;
	I->xcmax = a->xcmax;
	I->Fcmax = a->Fcmax;
	I->Ee = a->Ee;
	I->Wc = a->Wc;
	I->Wc0 = a->Wc + a->W;
	I->xe = a->x - a->xc;
	if (I->q) {
		const struct hb_arc_sample *f = hb_arc_at(s->arc, iv->first);

		I->te = f->t;
		I->vi = f->v;
	}
	while (s->ncol > 0 && s->col[s->ncol - 1].j >= s->j)
		s->ncol--;
	s->ncol_total = s->ncol > 0 ? s->col[s->ncol - 1].i + 1 : 0;
	if (s->ncol > 0 && s->col[s->ncol - 1].j + 1 >= s->j && !I->q)
		s->col[s->ncol - 1].tf = NAN;
	if (s->ncol > 0 && s->col[s->ncol - 1].j + 1 == s->j)
		s->col[s->ncol - 1].tf = NAN;
	for (int k = 0; k < s->nif; k++)
		s->ifc[k].ninst = 0;
	s->err[0] = s->endmsg[0] = '\0';
	s->end = HB_SIM_RUNNING;
	s->setup = 1;
	if (s->t >= s->sc.run.T)
		hbs_finish_T(s);
	else if (s->j >= s->sc.run.J) {
		s->end = HB_SIM_END_J;
		cnum_snprintf(s->endmsg, sizeof s->endmsg, "jump cap J = %ld reached at t = %.9g s",
		         s->sc.run.J, s->t);
	}
	return 0;
}

static int
same_bodies(const struct hb_scene *a, const struct hb_scene *b)
{
	return a->d.m1 == b->d.m1 && a->d.m2 == b->d.m2 && a->d.system == b->d.system;
}

int
hb_sim_set_scene(struct hb_sim *s, const struct hb_scene *sc, int *restarted, char *msg, size_t n)
{
	struct hb_scene nsc = *sc;
	int restart, rc;

	if (restarted)
		*restarted = 0;
	if ((rc = hb_scene_validate(&nsc, msg, n)) != 0)
		return rc;
	if (s->pend.active && (rc = hbs_pend_flush(s)) != 0) /* a chain goes on from the unit's end */
		return hb_status_set(msg, n, rc, "%s", s->err);
	if (s->chain || nsc.chain.n > 0)
		restart = !s->chain || nsc.chain.n == 0 || !hbs_chain_continues(s, &nsc);
	else
		restart = nsc.d.system != s->sc.d.system ||
		          memcmp(&nsc.init, &s->sc.init, sizeof nsc.init) != 0 ||
		          (s->I->q && (nsc.law != s->sc.law || nsc.ext != s->sc.ext ||
		                       !same_bodies(&nsc, &s->sc)));
	if (!restart && s->chain)
		hbs_chain_settle_flying(s); /* the new accelerations act from now on */
	{
		/* build for the new scene aside: on failure the simulator is exactly as it was */
		struct hb_scene old = s->sc;
		struct phase oldph[2] = { s->ph[0], s->ph[1] };
		int oldstepper[2] = { s->stepper[0], s->stepper[1] };
		int oldbuilt[2] = { s->built[0], s->built[1] };
		struct hb_sim_stats oldst = s->st;

		s->sc = nsc;
		memset(s->ph, 0, sizeof s->ph);
		if (build(s, msg, n) != 0) {
			hbs_phase_free(&s->ph[0]);
			hbs_phase_free(&s->ph[1]);
			s->sc = old;
			hbs_chain_bind(s); /* no larger than the arrays it had: cannot fail */
			memcpy(s->ph, oldph, sizeof s->ph);
			memcpy(s->stepper, oldstepper, sizeof s->stepper);
			memcpy(s->built, oldbuilt, sizeof s->built);
			s->st = oldst;
			return HB_ENOMEM;
		}
		hbs_phase_free(&oldph[0]);
		hbs_phase_free(&oldph[1]);
	}
	arc_set_max(s->arc, (size_t)nsc.run.max_samples);
	if (restart) {
		reset_state(s);
		if (restarted)
			*restarted = 1;
		return 0;
	}
	/* continue from the last sample with the new values (hb_sim_branch records it) */
	if (s->unrec_t < 0)
		s->unrec_t = hb_arc_at(s->arc, hb_arc_len(s->arc) - 1)->t;
	rc = hb_sim_seek(s, hb_arc_len(s->arc) - 1);
	if (rc == HB_OK && s->chain && s->end == HB_SIM_RUNNING)
		s->setup = 1; /* a chain's next interval begins with the new constants */
	return rc;
}

int
hb_sim_restart(struct hb_sim *s)
{
	reset_state(s);
	return 0;
}
