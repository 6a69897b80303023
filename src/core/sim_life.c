/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_life.c - a simulator's life around its run (sim.h): made for a scene
 * (hb_sim_new: the scene validated, the integrators and the chain's arrays
 * built, the run begun at t = 0), given a new scene part-way
 * (hb_sim_set_scene: built aside, then the run begun again or continued
 * from its last sample), restarted, freed or made again for a new scene in
 * its own memory (hbs_sim_renew, sim_life.h); and what it reports
 * (its end, error, scene, arc, statistics, collisions, the contact in
 * progress).  The run itself is sim.c's (hb_sim_advance); a seek is
 * sim_seek.c's.
 */
#include "sim_impl.h"
#include "sim_life.h"

static int
build(struct hb_sim *s, char *msg, size_t n)
{
	int q;

	if ((q = hbs_chain_bind(s)) != 0)
		return q == HB_ENOMEM ? hb_status_set(msg, n, HB_ENOMEM, "out of memory for the chain")
		                      : hb_status_set(msg, n, q, "the chain's scene names a body or "
		                                      "interface it does not have");
	for (q = 0; q < 2; q++)
		s->stepper[q] = s->sc.run.stepper == HB_STEPPER_AUTO ? HB_STEPPER_RK8PD : s->sc.run.stepper;
	if (hbs_work_reserve(s, MAXDIM, MAXFUN))
		return hb_status_set(msg, n, HB_ENOMEM, "out of memory for the integrator");
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
	hbs_reset_state(s);
	return s;
}

/* Frees what s holds but its own block, its arc and its root finder. */
static void
release(struct hb_sim *s)
{
	hbs_phase_free(&s->ph[0]);
	hbs_phase_free(&s->ph[1]);
	hbs_phase_free(&s->cph);
	hbs_work_free(s);
	if (s->eig)
		gsl_eigen_nonsymm_free(s->eig);
	if (s->Jdyn)
		gsl_matrix_free(s->Jdyn);
	if (s->lambda)
		gsl_vector_complex_free(s->lambda);
	hbs_chain_free(s);
	hbs_cluster_free(s);
	free(s->br);
	free(s->col);
	free(s->pend.s);
}

void
hb_sim_free(struct hb_sim *s)
{
	if (s == NULL)
		return;
	release(s);
	if (s->root)
		gsl_root_fsolver_free(s->root);
	arc_free(s->arc);
	free(s);
}

/* See sim_life.h. */
struct hb_sim *
hbs_sim_renew(struct hb_sim *s, const struct hb_scene *sc, char *msg, size_t n)
{
	struct hb_arc *arc;
	gsl_root_fsolver *root;

	release(s);
	arc = s->arc;
	root = s->root;
	/* as calloc left it for hb_sim_new, the kept three apart */
	memset(s, 0, sizeof *s);
	s->arc = arc;
	s->root = root;
	s->sc = *sc;
	if (hb_scene_validate(&s->sc, msg, n) != 0) {
		hb_sim_free(s);
		return NULL;
	}
	arc_clear(s->arc, (size_t)s->sc.run.max_samples);
	if (build(s, msg, n) != 0) {
		hb_sim_free(s);
		return NULL;
	}
	hbs_reset_state(s);
	return s;
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

/* The values so far of interface I's contact in progress (I->q), as collision i. */
static void
contact_live(const struct hb_sim *s, const struct iface *I, long i, struct hb_collision *out)
{
	memset(out, 0, sizeof *out);
	out->i = i;
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
	out->k = s->k0 + (int)(I - s->ifc);
}

int
hb_sim_contact_live(const struct hb_sim *s, struct hb_collision *out)
{
	if (!s->I->q || s->pend.active) /* (after a chain's seek, the state is the unit's end: none) */
		return 0;
	contact_live(s, s->I, s->ncol_total, out);
	return 1;
}

size_t
hb_sim_contacts_live(const struct hb_sim *s)
{
	size_t n = 0;

	if (s->pend.active)
		return 0;
	if (!s->chain)
		return s->I->q ? 1 : 0;
	for (int i = 0; i < s->nif; i++)
		n += s->ifc[i].q != 0;
	return n;
}

int
hb_sim_contact_live_nth(const struct hb_sim *s, size_t n, struct hb_collision *out)
{
	size_t r = 0;

	if (s->pend.active)
		return 0;
	if (!s->chain)
		return n == 0 ? hb_sim_contact_live(s, out) : 0;
	for (int i = 0; i < s->nif; i++)
		if (s->ifc[i].q && r++ == n) {
			contact_live(s, &s->ifc[i], s->ncol_total + (long)n, out);
			return 1;
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
			/*
			 * the driver's arrays may have been made again (sim_work.c):
			 * a chain's interval begins again from its interfaces' state
			 */
			if (s->chain)
				s->setup = 1;
			return HB_ENOMEM;
		}
		hbs_phase_free(&oldph[0]);
		hbs_phase_free(&oldph[1]);
		s->cx.built_dim = 0; /* a chain's clusters' driver: of the old tolerances */
	}
	arc_set_max(s->arc, (size_t)nsc.run.max_samples);
	if (restart) {
		hbs_reset_state(s);
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
	hbs_reset_state(s);
	return 0;
}
