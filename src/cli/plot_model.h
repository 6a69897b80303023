/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * plot_model.h - the figure model of `hybounce plot`: data -> panels,
 * axes (SI-prefixed units, ticks), series, shaded intervals, a legend, and
 * heat maps with their colour legend (plot_map.c), and their layout in
 * points.  Knows no plotting library and no engine run: plot_figures.c
 * fills it from a run, plot_sweep.c from a sweep's files, plot_fit.c from
 * a fit; plot_draw.c renders it through a backend (plot_backend.h),
 * plot_tex.c writes it as pgfplots source.
 *
 * Text in labels is a small markup: "x_c" sets c as a subscript, "F_c^max"
 * adds a superscript; a group in braces ("x_{c,1}") is one script.
 */
#ifndef HYBOUNCE_CLI_PLOT_MODEL_H
#define HYBOUNCE_CLI_PLOT_MODEL_H

#include <stddef.h>

enum { PLOT_MAX_PANELS = 12, PLOT_MAX_SERIES = 8, PLOT_MAX_TICKS = 16, PLOT_MAX_LEGEND = 8 };

/* The palette: Okabe-Ito colours, each with its own dash pattern, so that
 * curves stay apart for colour-blind readers and in greyscale. */
struct plot_style {
	double r, g, b;
	double dash[4];   /* on/off lengths in line widths; dash[0] == 0: solid */
	int ndash;
};
const struct plot_style *
plot_style_of(int k);

/* The shade of contact intervals (a light grey, 0..1 per channel). */
extern const double plot_shade_rgb[3];

struct plot_axis {
	char title[48];      /* markup: "x_c", "F_c^max", "t" */
	char unit[24];       /* prefixed: "µm", "kN", "" for a pure number */
	double scale;        /* data in SI times 1/scale = value shown */
	double lo, hi;       /* the range shown, in SI */
	int whole;           /* ticks on whole numbers only (an index) */
	int nticks;
	double tick[PLOT_MAX_TICKS];          /* in SI */
	char ticklabel[PLOT_MAX_TICKS][24];   /* in the unit shown */
	int log;             /* 1: a logarithmic axis (set before plot_axis_fit; its
	                      * ticks at decades, or 1-2-5 within one or two) */
	char base[24];       /* the SI base unit plot_axis_fit was given ("m") */
};

struct plot_series {
	char label[64];      /* legend text (markup), "" for none */
	double *x, *y;       /* SI, owned by the model; NaN breaks the line */
	size_t n;
	int style;           /* plot_style_of(style) */
	int markers;         /* 1: a dot at each point */
	int line;            /* 1: joined by lines */
};

struct plot_panel {
	struct plot_axis xa, ya;
	struct plot_series s[PLOT_MAX_SERIES];
	int ns;
	double *band0, *band1;   /* shaded x intervals, SI, owned; nband of them */
	size_t nband;
	int xlabels;             /* 1: this panel shows the x tick labels and title */
	/* layout, points from the top left of the figure: the frame */
	double fx, fy, fw, fh;
	/*
	 * A heat map (plot_map_set): mnx x mny cells, cell (i, j) spans
	 * mx[i] .. mx[i + 1] by my[j] .. my[j + 1] (SI, owned), its value
	 * mv[j * mnx + i] (NaN: no value, left white), coloured by
	 * plot_colormap over [vlo, vhi].
	 */
	double *mx, *my, *mv;
	size_t mnx, mny;
	double vlo, vhi;
	int vlog;                /* 1: colours spread over log10 of the values */
	/* 1: the colour legend of the map in the panel before it (set by
	 * plot_colorbar_add): a narrow strip right of that panel, its scale
	 * (the y axis) on its right */
	int colorbar;
};

struct plot_legend_entry {
	char label[64];
	int style;           /* series style, or -1 for the shade swatch */
	int markers, line;
};

struct plot_figure {
	double w, h;         /* points */
	double font;         /* points, tick labels; titles the same */
	double lw;           /* line width of the curves, points */
	char title[128];     /* above the legend, "" for none */
	int npanels;
	struct plot_panel p[PLOT_MAX_PANELS];
	int nlegend;
	struct plot_legend_entry legend[PLOT_MAX_LEGEND];
	double lx, ly, lw_box, lh_box;   /* the legend's box, points */
	int ncols;           /* panels per row */
};

/* An empty figure of w x h points. */
void
plot_figure_init(struct plot_figure *f, double w, double h);

/* Frees the data of every series and band. */
void
plot_figure_free(struct plot_figure *f);

/* A new panel (NULL when there are PLOT_MAX_PANELS). */
struct plot_panel *
plot_panel_add(struct plot_figure *f, const char *xtitle, const char *xunit,
               const char *ytitle, const char *yunit);

/* A series of n points (copied); -1 when out of memory or panel full. */
int
plot_series_add(struct plot_panel *p, const char *label, const double *x, const double *y,
                size_t n, int style, int line, int markers);

/* Shaded x intervals [a[k], b[k]] (copied); -1 when out of memory. */
int
plot_bands_set(struct plot_panel *p, const double *a, const double *b, size_t n);

/* A legend entry (style -1: the shade). */
void
plot_legend_add(struct plot_figure *f, const char *label, int style, int line, int markers);

/*
 * Ranges, units and ticks of every axis from the data (x axes given a
 * range with xlo < xhi keep it: the state's t axis runs 0 .. t_end), then
 * the layout: a title strip, the legend strip, the panels in rows of
 * f->ncols, tick labels and titles in the margins.  text_width(ctx, text,
 * size) measures plain text (NULL: an estimate of 0.55 em per character).
 */
void
plot_figure_layout(struct plot_figure *f, double (*text_width)(void *ctx, const char *s,
                   double size), void *ctx);

/*
 * Ticks of [lo, hi] at about `want` of them, 1-2-5 steps (whole: steps of
 * at least 1): *n ticks into t (at most PLOT_MAX_TICKS).
 */
void
plot_ticks(double lo, double hi, int want, int whole, double *t, int *n);

/* The range and unit of an axis from its data's extent [lo, hi] (SI) and
 * its SI base unit ("m", "N", "m/s", "" ...): pads, prefixes and ticks. */
void
plot_axis_fit(struct plot_axis *a, double lo, double hi, const char *base, int keep, int want);

/* Splits markup into runs: kind 0 normal, 1 subscript, 2 superscript. */
struct plot_run {
	char text[48];
	int kind;
};
int
plot_markup(const char *s, struct plot_run *runs, int max);

/* The width of markup text at size (scripts at 0.7 of it); text_width as
 * for plot_figure_layout. */
double
plot_text_width(const char *markup, double size,
                double (*text_width)(void *ctx, const char *s, double size), void *ctx);

/*
 * The sequential colour map of heat maps at t in [0, 1] (viridis: its
 * lightness rises with t, so that it reads in greyscale and for
 * colour-blind readers); NaN gives white.
 */
void
plot_colormap(double t, double rgb[3]);

/* A heat map on p (plot_panel's mx, my, mv: copied); -1 when out of memory. */
int
plot_map_set(struct plot_panel *p, const double *x_edges, size_t nx, const double *y_edges,
             size_t ny, const double *v, double vlo, double vhi, int vlog);

/* The colour of value v of p's map (plot_colormap of its place in vlo .. vhi). */
void
plot_map_colour(const struct plot_panel *p, double v, double rgb[3]);

/*
 * The colour legend of the map of panel `of`, as a panel of its own
 * after it: its scale titled title (markup) in unit (SI base), over
 * [of->vlo, of->vhi] (logarithmic where of->vlog).  NULL when full or
 * out of memory.
 */
struct plot_panel *
plot_colorbar_add(struct plot_figure *f, const struct plot_panel *of, const char *title,
                  const char *unit);

/* The position of v on axis a: 0 at a->lo, 1 at a->hi (log10 on a log axis). */
double
plot_axis_pos(const struct plot_axis *a, double v);

/* "x_c (µm)": the axis title with its unit shown. */
void
plot_axis_label(const struct plot_axis *a, char *buf, size_t n);

#endif
