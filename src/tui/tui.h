/*
 * tui.h - the explorer's state, shared by its files (private to src/tui/).
 *
 * app.c owns the loop and every change of state (keys -> actions -> sim
 * calls); the pane_*.c files only read the state and draw it; pickers.c
 * and script.c are helpers called by app.c.
 *
 * The cursor is a sample index into the current run's arc (always valid:
 * < arc_len); tcur is the playback time it follows while playing.
 */
#ifndef HYBOUNCE_TUI_H
#define HYBOUNCE_TUI_H

#include <stddef.h>

#include "app.h"
#include "layout.h"
#include "preset.h"
#include "sim.h"

enum { APP_MAX_PINS = 5 };

enum view { VIEW_WHOLE = 0, VIEW_FOLLOW, VIEW_ZOOM, VIEW_LOOP, VIEW_J, VIEW_COUNT };
enum focus { FOCUS_TABLE = 0, FOCUS_PARAMS };
enum overlay { OV_NONE = 0, OV_HELP, OV_LAW, OV_PRESET, OV_PROMPT };
enum prompt_kind { PROMPT_EDIT = 0, PROMPT_EXPORT };

struct pin {
	struct sim *sim;
	char label[64];
};

struct app {
	const struct app_options *opt;
	struct sim *sim;
	char preset[64];            /* name shown in the status line */
	char preset_path[512];
	char run_label[64];         /* legend label of the current run */

	struct pin pin[APP_MAX_PINS];
	int npins;

	size_t cursor;              /* sample index in sim_arc(sim) */
	double tcur;                /* playback time, s */
	int playing;
	double speed;               /* playback: simulated s per wall s */
	int slowmo;                 /* slow motion through contacts enabled */
	int in_slow;                /* slow motion in effect now */

	int view;                   /* enum view */
	long zoom_i;                /* collision shown by zoom/loop (-1: the live contact) */

	int focus;                  /* enum focus */
	long table_sel, table_top;
	int param_sel, param_top;

	int overlay;                /* enum overlay */
	int pick_sel, pick_top, help_top;
	struct preset_info *presets;
	int npresets;
	int prompt_kind;
	char prompt_key[48];
	char prompt_title[96];
	char prompt_buf[256];

	char msg[512];
	int msg_error;              /* the message reports a failure */

	int braille, colour;
	struct layout L;
	int quit;
	int exit_status;
	double budget;              /* compute seconds per frame */
	unsigned long frames;
};

/* Cells of text drawing with clipping (pane_status.c). */
void
tui_puts(int y, int x, int maxw, const char *s, int attr);

/* Drawing (pane_*.c): read the state, draw into stdscr. */
void pane_plot_draw(const struct app *a);
void pane_table_draw(const struct app *a);
void pane_params_draw(const struct app *a);
void pane_status_draw(const struct app *a);
void pane_help_draw(const struct app *a);
void pane_too_small_draw(const struct app *a);
void pickers_draw(const struct app *a);

/* The whole frame: erase, draw every pane, refresh. */
void
app_draw(struct app *a);

/* Handles one key (as from getch) and returns nothing; sets a->quit to leave. */
void
app_key(struct app *a, int ch);

/*
 * One frame of work without input: computes for the frame's budget and
 * advances playback by the wall time since the last call.  Returns 1 while
 * something is still going on (computing or playing), 0 when idle.
 */
int
app_tick(struct app *a);

/* Recomputes the layout from LINES/COLS. */
void
app_relayout(struct app *a);

/* Parameter panel rows (pane_params.c): the row list built from scene_key. */
struct param_row {
	int key;          /* scene_key index, or -1 for a section heading */
	char section[16];
};
int
params_rows(const struct scene *sc, struct param_row *rows, int max);

/* Plot helpers shared by the panes (pane_plot.c). */
const struct collision *
app_collision(const struct app *a, long i, struct collision *live);
long
app_ncollisions(const struct app *a);   /* completed + the live one (if any) */

/* Opens a preset as the current run (pins are kept); errors go to the message line. */
void
app_open_preset(struct app *a, const char *name);

/* Changes the law of the current run at the cursor (sim_set_scene). */
void
app_set_law(struct app *a, const char *law);

/* Pickers (pickers.c): keys while a picker is open. */
void
pickers_key(struct app *a, int ch);

/* Scripted mode (script.c).  Returns the exit status. */
int
script_run(struct app *a, const char *path, char *msg, size_t n);

/* Writes the current screen as text (UTF-8) to path.  Returns 0 or -1. */
int
script_dump(const char *path);

/* Sets the message line (printf-like). */
void
app_msg(struct app *a, int error, const char *fmt, ...) __attribute__((format(printf, 3, 4)));

#endif
