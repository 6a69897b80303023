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
 * This driver steps every numeric flow interval: a two-body scene's, in
 * the layouts of sim_flow.c, and a chain's clusters of contacts, whose
 * system sim_cluster*.c builds (docs/chains.md section 8a): what the
 * driver asks of a system (its right-hand side, its watched functions,
 * the state unpacked, a jump) is the phase's.  What is per interface is
 * written once for both systems: the watched terms and the mode of a step
 * (sim_iface.h), a contact's scales (hbs_contact_scale), the stiffness of
 * one interface's flow (sim_stiff.c).
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
 *
 * This file is the run: begun at t = 0 (hbs_reset_state) and advanced
 * (hb_sim_advance: a pair's flow intervals set up and stepped here, a
 * chain's units of work in sim_chain.c and sim_cluster*.c).  A simulator
 * made, given a new scene, restarted, freed and read: sim_life.c; a run
 * continued from one of its samples: sim_seek.c.
 */
#include "sim_impl.h"
#include "sim_iface.h"
#include "clock.h"

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
	memset(s->gmax, 0, (size_t)s->dim.f * sizeof *s->gmax);
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

/*
 * One accepted step of the numeric phase, with what follows from it: the
 * pair's, and a chain's clusters in contact (sim_cluster_step.c begins
 * their step).
 */
static int
numeric_step(struct hb_sim *s)
{
	struct phase *p = s->cur;
	const struct hb_scene *sc = &s->sc;
	double t = s->t, t1 = sc->run.T, kinks[4];
	int nk, load_kink = 0, rc;

	if (s->chain) {
		int jumped = 0;

		if ((rc = hbs_cluster_step_begin(s, &t1, &jumped)) || jumped)
			return rc;
	} else {
		/* a state already outside C where the interval begins jumps at once (rule R2) */
		double f0 = hbs_watch_indicator(s, p, s->t, s->u);

		if (f0 < 0.0)
			return hbs_jump(s, HB_LOCATE_START, 0, 0.0, f0, f0);
		nk = sc->run.kinks ? hb_scene_load_kinks(sc, t, t1, kinks, 4) : 0;
		if (nk > 0) {
			t1 = kinks[0];
			load_kink = 1;
		}
	}
	if (p->q && sc->run.h_max > 0 && t + sc->run.h_max < t1) {
		t1 = t + sc->run.h_max;
		load_kink = 0;
	}
	hbs_ucopy(s, s->u0, s->u);
	s->t0 = t;
	s->hug = hbs_hugging(s, s->u0);
	if (!s->chain)
		set_mode(s);
	if ((rc = hbs_evolve(s, &p->known, p->d->e, p->d->c, p->d->s, &p->sys, s->t0, s->u0, t1, &t,
	                     &s->h, s->u, &s->H)))
		return rc;
	if (s->first && t < t1) /* the step this interval's start took, in units of Tc */
		s->h1[p->q] = s->H / s->Tc;
	s->first = 0;
	{
		double dt0, dh;

		/* on Phi = 0 to the noise, the interpolant's error would exceed the noise: re-step */
		s->use_dense = !s->hug && hb_dop853_last(p->d->s, &dt0, &dh) == 0 && dt0 == s->t0;
	}
	hbs_ucopy(s, s->u1, s->u);
	if ((rc = hbs_after_step(s, load_kink && t == t1)))
		return rc;
	if (s->end == HB_SIM_RUNNING && !s->setup &&
	    (rc = s->chain ? hbs_cluster_stiffness(s) : hbs_stiffness(s)))
		return rc;
	if (s->end == HB_SIM_RUNNING && !s->setup && s->t >= sc->run.T) {
		/* the horizon: the last sample is the end */
		if ((rc = hbs_push_sample(s, HB_ARC_END)))
			return rc;
		hbs_finish_T(s);
	}
	return 0;
}

/*
 * The run begun again at t = 0 from the scene's initial state, the arc
 * holding its first sample (hb_sim_new, hb_sim_restart, a restart by
 * hb_sim_set_scene, a chain's replay in sim_seek.c).
 */
void
hbs_reset_state(struct hb_sim *s)
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
			rc = s->cx.nact ? numeric_step(s) : hbs_chain_flight(s);
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
