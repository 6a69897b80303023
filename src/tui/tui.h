/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * tui.h - the explorer's state, shared by its files (private to src/tui/).
 *
 * app.c owns the loop; a key goes to the mode on top of the stack of
 * modes (mode.h: the explorer, presentation, the help, the log, the
 * pickers, the prompt, the data table, the sweep view, each in its own
 * file with its own key table), whose table gives the function, in the
 * file that owns that part of the state: nav.c, playback.c, edit.c,
 * runs.c, log.c, mouse.c.  The pane_*.c files only read the state and
 * draw it.  Calls go one way, from the loop and the dispatch down to the
 * modes and the panes: a mode reports through app_msg (log.c), lays the
 * screen out again with app_relayout (relayout.c), and a prompt or a
 * picker reports to the function its opener gave (prompt_fn, pick_fn);
 * the shared primitives are draw.c (text, boxes, wrapping), cursor.c (the
 * cursor and the run's collisions), names.c (export names), textov.c
 * (scrolled text in a box), fitov_draw.c and sweep_obs.c.
 * tests/cli/calls.sh measures the cycles of calls left among the files
 * (nm over the objects) against tests/cli/calls.allow, empty now: the
 * loop (app.c) and a script (script.c) both play frames (frame.c).
 *
 * The cursor is a sample index into the current run's arc (always valid:
 * < hb_arc_len); tcur is the playback time it follows while playing.
 */
#ifndef HYBOUNCE_TUI_H
#define HYBOUNCE_TUI_H

#include <stddef.h>

#include "app.h"
#include "mode.h"
#include "layout.h"
#include "preset.h"
#include "sim.h"

enum { APP_MAX_PINS = 3, APP_LOG_MAX = 64, APP_UNDO_MAX = 32 };

enum view { VIEW_WHOLE = 0, VIEW_FOLLOW, VIEW_ZOOM, VIEW_LOOP, VIEW_J, VIEW_COUNT };
enum focus { FOCUS_TABLE = 0, FOCUS_PARAMS };
enum { APP_MODE_MAX = 8 };     /* modes open at once (mode.h) */
enum pick_kind { PICK_LAW = 0, PICK_PRESET };
enum prompt_kind { PROMPT_EDIT = 0, PROMPT_EXPORT, PROMPT_SEARCH, PROMPT_SWEEP, PROMPT_ADD };
enum { PROMPT_DATA = 16, PROMPT_FIT };  /* overlay_fit.c */

/*
 * How a prompt reports (prompt.c calls the function its opener gave, never
 * a mode by name): PROMPT_ENTER with the text, PROMPT_CANCEL (Esc), or
 * PROMPT_TYPED with the text after each key while it stays open.
 */
enum { PROMPT_ENTER = 0, PROMPT_CANCEL, PROMPT_TYPED };
struct app;
typedef void prompt_fn(struct app *a, const char *text, int how);
/* How a picker (pickers.c) reports the entry chosen with Enter: a law's name, a preset's path. */
typedef void pick_fn(struct app *a, const char *choice);

struct pin {
	struct hb_sim *sim;
	char label[96];             /* what differs from the current run */
	int branched;               /* the run contains a "branch here" */
};

/* physics.c: the physics checks of the current run, once it has ended. */
struct app_physics {
	int valid;                  /* checked, for the run as it stands */
	int failed;                 /* checks failed (0..3) */
	size_t nbad;                /* collisions that break what the law allows */
	unsigned char *flags;       /* per collision: HB_CHECK_BAD_W | HB_CHECK_BAD_E */
	size_t nflags;
};

struct app {
	const struct app_options *opt;
	struct hb_sim *sim;
	char preset[64];            /* name shown in the status line */
	char preset_path[512];
	char run_label[96];         /* legend label of the current run */

	struct pin pin[APP_MAX_PINS];
	int npins;

	size_t cursor;              /* sample index in hb_sim_arc(sim) */
	double tcur;                /* playback time, s */
	double want_t;              /* after an edit: the cursor goes back to this t (-1: none) */
	int branch_armed;           /* the next edit continues from the cursor (b) */
	double branch_t;            /* the run contains a branch at (branch_t, branch_j); -1: none */
	long branch_j;
	int nbranches;
	int compare;                /* table differences against pin compare-1 (0: off) */
	int present;                /* presentation mode (T): 1 dark, 2 light theme */
	double tick_last;           /* app_tick: when the last frame was (monotonic s; 0: none) */
	int script_live;            /* script.c: a script plays on the real screen */
	int present_view, present_slowmo;   /* what T puts back */
	double slow_t0, slow_td;    /* in slow motion: the contact's start and the duration it is timed by */
	/*
	 * Presentation: each quantity's range (x, x_c, F_c) over every sample
	 * seen so far of the runs drawn, so that an axis holds its scale.
	 */
	struct {
		const struct hb_sim *sim[APP_MAX_PINS + 1];
		size_t seen[APP_MAX_PINS + 1];
		int n;
		struct hb_scene scene;  /* the current run's, as last seen: an edit restarts the same run */
		double lo[3], hi[3];
	} hold;
	int demo_ctx;               /* a --script demo on the real screen: its CTX_DEMO_*; 0: none */
	char caption[512];          /* a script's caption (wrapped over the message line) */
	int caption_large;          /* ... shown large, in a box over the plots */
	int playing;
	double speed;               /* playback: simulated s per wall s */
	int slowmo;                 /* slow motion through contacts enabled */
	int in_slow;                /* slow motion in effect now */

	int view;                   /* enum view */
	long zoom_i;                /* collision shown by zoom/loop (-1: the live contact) */

	int focus;                  /* enum focus */
	long table_sel, table_top;  /* table_sel: a collision's index (shown or not) */
	int table_k;                /* the table shows interface table_k - 1 alone (i); 0: every one */
	int param_sel, param_top;

	/*
	 * The modes open (mode.h), the explorer (mode_main) first: the top one
	 * takes the keys.  modes: the registry, every mode (the help lists them).
	 */
	const struct mode *mode[APP_MODE_MAX];
	int nmodes;
	const struct mode *const *modes;
	int pick_kind;              /* enum pick_kind: the list of the open picker */
	int pick_sel, pick_top, help_top;
	struct hb_preset_info *presets;
	int npresets;
	int prompt_kind;
	prompt_fn *prompt_done;      /* what the open prompt reports to (prompt_open) */
	pick_fn *pick_done;          /* what the open picker reports to (mode_law, mode_preset) */
	char prompt_key[48];
	char prompt_title[640];
	char prompt_buf[256];
	size_t prompt_pos;          /* the caret: a byte offset into prompt_buf */
	int prompt_fresh;           /* the text is as given: the first printable key replaces it */

	char msg[512];
	int msg_error;              /* the message reports a failure */
	char *log[APP_LOG_MAX];     /* every message, oldest first (a ring) */
	int log_n, log_head, log_top;
	int search_from;            /* panel row when the search began */
	char search_text[64];       /* the last search (n/N) */
	int search_i;               /* which of its matches is selected */

	struct hb_scene origin;     /* the scene as opened (U resets a value to it) */
	struct hb_scene undo[APP_UNDO_MAX];   /* the scenes before the last edits (u), oldest first */
	char undo_what[APP_UNDO_MAX][160];    /* what each edit was */
	int nundo;

	int braille, colour;
	struct layout L;
	int quit;
	int exit_status;
	double budget;              /* compute seconds per frame */
	unsigned long frames;
	struct fitov *fitov;        /* measured data and the fit (overlay_fit.c), or NULL */
	struct sweep_view *sv;      /* the sweep view (sweep_view.c), NULL until S */
	struct errbar *errbar;      /* error bars (errbar.c), NULL until E */
	struct app_physics phys;    /* physics.c */
	struct plot_sums *psum;     /* plot_summary.c: what the plots draw of long arcs (NULL: none) */
	struct spacetime *st;       /* the space-time view (spacetime.c), NULL until V */
};

/* What a key of a mode's table does (mode.h). */
typedef void action_fn(struct app *a);

action_fn act_play, act_step_fwd, act_step_back, act_prev_jump, act_next_jump,
	act_prev_coll, act_next_coll, act_scrub_back, act_scrub_fwd, act_home, act_end,
	act_faster, act_slower, act_slowmo, act_view, act_zoom, act_loop, act_jview,
	act_focus, act_up, act_down, act_pgup, act_pgdn, act_top, act_bottom,
	act_prev_section, act_next_section, act_search, act_enter,
	act_nudge_up, act_nudge_down, act_branch, act_law, act_preset, act_restart,
	act_pin, act_unpin, act_compare, act_study3, act_export, act_log, act_present,
	act_search_next, act_search_prev, act_undo, act_reset, act_table_iface, act_add;

/* nav.c: the cursor and the selections (the first four: cursor.c). */
/*
 * The demo (mode_demo.c): the viewer's key ch in the context a->demo_ctx;
 * returns 1 when the demo's table bound it (q quits), 0 for any other key.
 * demo_hint: the footer's text for a->demo_ctx ("demo: any key pauses, q
 * quits"), printed from the table.  Returns buf.
 */
int demo_viewer_key(struct app *a, int ch);
char *demo_hint(const struct app *a, char *buf, size_t n);
void cursor_set(struct app *a, size_t i);
void cursor_clamp(struct app *a);                 /* keeps it < hb_arc_len */
long coll_at_cursor(const struct app *a);         /* the row's collision at the cursor, or -1 */
int coll_in_progress(const struct app *a, const struct hb_collision *c); /* c is in progress at the cursor */
void cursor_to_collision(struct app *a, long i);  /* to its commencement; selects its row */
/*
 * The collisions table's rows (cursor.c): every collision, or with i on a
 * chain those of one interface.  table_iface: that interface k, or -1
 * (every one; a scene without it now).  table_shows: collision i is a row.
 * table_nrows: the rows.  table_row_of: the row of collision i (where it
 * would be when not shown).  table_row_coll: the collision of row r, or -1.
 */
int table_iface(const struct app *a);
int table_shows(const struct app *a, long i);
long table_nrows(const struct app *a);
long table_row_of(const struct app *a, long i);
long table_row_coll(const struct app *a, long r);
double view_span(const struct app *a);
void zoom_on(struct app *a, int view);
void sel_move(struct app *a, long d);
/* search: moves the panel selection to the first row whose key or label holds text */
void search_do(struct app *a, const char *text, int final);

/* playback.c */
double speed_default(double T);
int playback_tick(struct app *a, double dt);      /* 1 while playing */
const char *stiff_note(const struct app *a, char *buf, size_t n);
/* Presentation: each axis's range over the samples of the runs drawn so far (a->hold). */
void hold_update(struct app *a);

/* edit.c: the what-if loop. */
void edit_value(struct app *a, const char *key, const char *text);
int param_key_index(const struct app *a);

/* runs.c */
struct hb_sim *load_sim(const char *name, const char *const *sets, int nsets, char *path,
                     size_t pn, char *msg, size_t n);
void app_adopt(struct app *a, struct hb_sim *s, const char *path);
void app_label_runs(struct app *a);               /* legend labels from what differs */
void pins_clear(struct app *a);
void export_do(struct app *a, const char *base);
/*
 * path itself into out when nothing is there (0), else the first of
 * STEM-2.EXT, STEM-3.EXT ... that is free (1): an export never replaces an
 * earlier one unasked.  -1 when none is (up to -999) or out is too small.
 */
int tui_unused_name(const char *path, char *out, size_t n);   /* names.c */
/* 1 if a file (or a link, even dangling) is at path: an export must not replace it (names.c). */
int tui_path_taken(const char *path);

/* prompt.c */
void prompt_open(struct app *a, int kind, prompt_fn *done, const char *text, const char *fmt, ...)
	__attribute__((format(printf, 5, 6)));

/* log.c: the log's memory. */
void log_free(struct app *a);
const char *log_get(const struct app *a, int i);  /* i-th message, oldest first */

/*
 * textov.c: a text overlay (the help, the log): a box over the plots and
 * the bottom pane whose lines scroll.  lines(a, out, ctx) gives every line
 * to out (wrapped to width w); *top is the first line shown.
 */
struct rect;
typedef void textov_out(void *ctx, int k, const char *line);
typedef int textov_lines(const struct app *a, int w, textov_out *out, void *ctx);
int textov_width(const struct app *a);
void textov_draw(const struct app *a, const char *title, textov_lines *lines, int top);
void textov_scroll(struct app *a, textov_lines *lines, int *top, int d);  /* d: lines; +-1000000: a page */
int textov_page(const struct app *a);                                   /* the rows shown */
void textov_wheel(struct app *a, textov_lines *lines, int *top);        /* KEY_MOUSE: the wheel */
/* An overlay box with a border on all four sides, cleared inside; returns the inner rect (draw.c). */
struct rect box_draw(int y, int x, int h, int w, const char *title);

/* physics.c: checks the ended run; failures to the message line and the log. */
void physics_run(struct app *a);
void physics_forget(struct app *a);
unsigned physics_flag(const struct app *a, long i);   /* HB_CHECK_BAD_* of collision i */

/* mouse.c */
void mouse_event(struct app *a);

/* A script's caption (log.c): on the message line wrapped, or large in a box; "" clears. */
void app_caption(struct app *a, const char *text, int large);

/* Cells of text drawing with clipping (draw.c): a cut text ends in tui_cut_mark(). */
void
tui_puts(int y, int x, int maxw, const char *s, int attr);
const char *tui_cut_mark(void);
/*
 * Draws s word-wrapped into rows of w columns from (y, x), at most maxrows
 * (draw.c); a text that needs more ends in the cut mark.  Returns the rows
 * drawn.  tui_wrap_rows: the rows s needs at width w.
 */
int tui_wrap_draw(int y, int x, int w, int maxrows, const char *s, int attr);
int tui_wrap_rows(const char *s, int w);
/*
 * Wraps s into lines of at most w columns at blanks (a word longer than w
 * is cut), calling out(ctx, k, line) for each (out may be NULL); lines
 * after the first get indent blanks before them.  Returns the line count.
 */
int tui_wrap(const char *s, int w, int indent, void (*out)(void *, int, const char *), void *ctx);

/* Drawing (pane_*.c): read the state, draw into stdscr. */
void pane_plot_draw(const struct app *a);
void pane_table_draw(const struct app *a);
void pane_params_draw(const struct app *a);
void pane_status_draw(const struct app *a);
void pane_too_small_draw(const struct app *a);
/* The abscissa range the plots show (t, or j in the (t, j) view). */
void plot_view_range(const struct app *a, double *t0, double *t1);
/* f: the view as a figure (figure.c). */
action_fn act_figure;
/* The abscissa (t, or j in the (t, j) view) under screen column x of the plots; -1 outside. */
int plot_abscissa_at(const struct app *a, int x, double *t);

/* The whole frame: erase, draw every pane, refresh (frame.c). */
void
app_draw(struct app *a);

/* Handles one key (as from getch) through the top mode (mode.h); sets a->quit to leave (actions.c). */
void
app_key(struct app *a, int ch);

/*
 * One frame of work without input (frame.c): computes for the budget and
 * advances playback by the wall time since the last call.  Returns 1 while
 * something is still going on (computing or playing), 0 when idle.
 */
int
app_tick(struct app *a);

/* Recomputes the layout from LINES/COLS (relayout.c). */
void
app_relayout(struct app *a);

/* Parameter panel rows (pane_params.c): the row list built from hb_scene_key. */
struct param_row {
	int key;          /* hb_scene_key index, or -1 for a section heading */
	char section[16];
};
int
params_rows(const struct hb_scene *sc, struct param_row *rows, int max);

/* Plot helpers shared by the panes (pane_plot.c). */
const struct hb_collision *
app_collision(const struct app *a, long i, struct hb_collision *live);
long
app_ncollisions(const struct app *a);   /* completed + the live one (if any) */

/* Opens a preset as the current run (pins are kept); errors go to the message line. */
void
app_open_preset(struct app *a, const char *name);

/* Changes the law of the current run at the cursor (hb_sim_set_scene). */
void
app_set_law(struct app *a, const char *law);

/* Pickers (pickers.c): the list of the open picker (a->pick_kind); its modes: pick_law.c, pick_preset.c. */
action_fn pick_up, pick_down, pick_pgup, pick_pgdn, pick_home, pick_end, pick_close, pick_choose;
void pickers_draw(const struct app *a, const struct mode *self);
/*
 * A picker's key table (mode.h's mode_key; curses.h and mode.h where it is
 * expanded): the moves through the list, Enter (what it does: HELP, its
 * footer word WORD) and Esc q.
 */
#define PICK_KEYS(help, word)                                                                  \
	{ KEY_UP, 'k', CTX_ANY, pick_up, "Up k", "the previous entry", NULL },                 \
	{ KEY_DOWN, 'j', CTX_ANY, pick_down, "Down j", "the next entry", NULL },               \
	{ KEY_PPAGE, 0, CTX_ANY, pick_pgup, "PgUp", "a page up", NULL },                        \
	{ KEY_NPAGE, 0, CTX_ANY, pick_pgdn, "PgDn", "a page down", NULL },                      \
	{ KEY_HOME, 'g', CTX_ANY, pick_home, "Home g", "the first entry", NULL },              \
	{ KEY_END, 'G', CTX_ANY, pick_end, "End G", "the last entry", NULL },                  \
	{ '\n', KEY_ENTER, CTX_ANY, pick_choose, "Enter", help, word },                        \
	{ 27, 'q', CTX_ANY, pick_close, "Esc q", "close, choosing nothing", "closes" }

/* Scripted mode (script.c).  Returns the exit status. */
int
script_run(struct app *a, const char *path, char *msg, size_t n);

/* Writes the current screen as text (UTF-8) to path, atomically (outputs.h).
 * Returns 0, or -1 with "PATH: reason; accepted: ..." in msg. */
int
script_dump(const char *path, char *msg, size_t n);

/* overlay_fit.c: measured data over the scene, and the fit (D, M, F; --data). */
struct canvas;
action_fn act_data, act_data_table, act_fit;
/* errbar.c: error bars (E) */
action_fn act_errbar;
int errbar_on(const struct app *a);
int errbar_tick(struct app *a);                           /* 1 while the second run computes */
void errbar_free(struct app *a);
const struct hb_collision *errbar_find(const struct app *a, long i); /* NULL: none (yet) */
void errbar_state(const struct app *a, char *buf, size_t n);          /* "" when off */
void errbar_format(const char *name, double v, double err, char *buf, size_t n);
int fitov_load(struct app *a, const char *path, char *msg, size_t n); /* 0 or -1 */
int fitov_loaded(const struct app *a);
void fitov_announce(struct app *a);                       /* what is loaded, to the message line */
void fitov_free(struct app *a);
int fitov_tick(struct app *a);                            /* 1 while fitting */
/* The data table M (mode_fit.c), drawn by fitov_draw.c. */
void fitov_draw(const struct app *a, const struct mode *self);
void fitov_plot_marks(const struct app *a, struct canvas *c, int q_is_x, double t0, double t1);
void fitov_table_note(const struct app *a, long i, char *line, size_t n); /* i -1: header */
/* A recording is shown (its envelope, onsets and the run's impacts on the plots' t axis). */
int fitov_recording(const struct app *a);
double fitov_recording_peak(const struct app *a);               /* full scale 1 */
void fitov_plot_recording(const struct app *a, struct canvas *c, double t0, double t1);

/* Sets the message line (printf-like). */
void
app_msg(struct app *a, int error, const char *fmt, ...) __attribute__((format(printf, 3, 4)));

/* The sweep view (sweep_view.c, pane_sweep.c): S opens it; while open it takes the keys. */
action_fn act_sweep;
int sweep_view_open(const struct app *a);
int sweep_view_tick(struct app *a);              /* polls the curves; 1 while computing */
void sweep_view_free(struct app *a);
void pane_sweep_draw(const struct app *a, const struct mode *self);

#endif
