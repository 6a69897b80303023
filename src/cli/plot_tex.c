/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * plot_tex.c - a figure model as pgfplots source: a standalone LaTeX file
 * that compiles with pdflatex (pgfplots; the standalone class where it is
 * installed, else article on a page of the figure's size), and its
 * data file beside it, which the .tex reads by name.  Each panel is one
 * axis environment placed where the model's layout puts its frame; the
 * data are in the units the axes show (the SI prefix applied), one pair
 * of columns (x, y) per curve, shorter curves padded with nan; contact
 * intervals are \fill rectangles in the .tex itself.  Lengths are in bp
 * (1/72 in), the points of the model.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cnum.h"
#include "plot_tex.h"

/* Text for TeX: the markup's symbols in math mode, the rest as text. */
static void
tex_text(FILE *f, const char *s, int math)
{
	for (; *s != '\0'; s++) {
		if (strncmp(s, "\xce\x9b", 2) == 0) {                 /* Λ */
			fputs(math ? "\\Lambda " : "$\\Lambda$", f);
			s++;
		} else if (strncmp(s, "\xce\x94", 2) == 0) {          /* Δ */
			fputs(math ? "\\Delta " : "$\\Delta$", f);
			s++;
		} else if (strncmp(s, "\xce\xa3", 2) == 0) {          /* Σ */
			fputs(math ? "\\Sigma " : "$\\Sigma$", f);
			s++;
		} else if (strncmp(s, "\xc3\x97", 2) == 0) {          /* × */
			fputs(math ? "\\times " : "$\\times$", f);
			s++;
		} else if (strncmp(s, "\xc2\xb5", 2) == 0) {          /* µ */
			fputs(math ? "\\mu " : "$\\mu$", f);
			s++;
		} else if (strncmp(s, "\xe2\x88\x92", 3) == 0) {      /* − */
			fputs(math ? "-" : "$-$", f);
			s += 2;
		} else if (strchr("#$%&_{}", *s) != NULL) {
			fprintf(f, "\\%c", *s);
		} else if (*s == '|') {
			fputs(math ? "|" : "\\textbar{}", f);
		} else if (*s == '\\' || *s == '^' || *s == '~') {
			fputs(*s == '\\' ? "\\textbackslash{}" : *s == '^' ? "\\^{}" : "\\~{}", f);
		} else {
			fputc(*s, f);
		}
	}
}

/*
 * Markup as TeX: a word followed by sub- or superscripts becomes math
 * ($F_{\mathrm{c}}^{\mathrm{max}}$), a single letter alone too ($e$, $i$)
 * where letters is 1 (not in a unit: N, m); other words stay text.
 */
static void
tex_markup(FILE *f, const char *markup, int letters)
{
	struct plot_run r[16];
	int n = plot_markup(markup, r, 16);

	for (int k = 0; k < n; k++) {
		if (r[k].kind != 0)
			continue;   /* written with the word before it */
		{
			const char *t = r[k].text;
			int scripted = k + 1 < n && r[k + 1].kind != 0;
			const char *last = strrchr(t, ' '), *w;
			char pre[48];

			w = last != NULL ? last + 1 : t;
			if (last != NULL) {
				size_t l = (size_t)(w - t);

				memcpy(pre, t, l);
				pre[l] = '\0';
			} else {
				pre[0] = '\0';
			}
			if (!scripted) {
				/* single letters (between spaces or brackets) as math */
				for (const char *c = t; *c != '\0'; c++) {
					int alone = letters &&
					            ((*c >= 'a' && *c <= 'z') || (*c >= 'A' && *c <= 'Z')) &&
					            (c == t || strchr(" (", c[-1]) != NULL) &&
					            (c[1] == '\0' || strchr(" )", c[1]) != NULL);
					char one[2] = { *c, 0 };

					if (alone)
						fprintf(f, "$%c$", *c);
					else if (((unsigned char)*c & 0x80) != 0) {
						/* a UTF-8 sequence whole */
						char seq[5];
						int len = 1;

						seq[0] = *c;
						while (len < 4 && ((unsigned char)c[len] & 0xc0) == 0x80) {
							seq[len] = c[len];
							len++;
						}
						seq[len] = '\0';
						tex_text(f, seq, 0);
						c += len - 1;
					} else
						tex_text(f, one, 0);
				}
				continue;
			}
			tex_text(f, pre, 0);
			fputc('$', f);
			tex_text(f, w, 1);
			while (k + 1 < n && r[k + 1].kind != 0) {
				k++;
				fputs(r[k].kind == 1 ? "_{\\mathrm{" : "^{\\mathrm{", f);
				tex_text(f, r[k].text, 1);
				fputs("}}", f);
			}
			fputc('$', f);
		}
	}
}

static void
tex_axis_label(FILE *f, const struct plot_axis *a)
{
	tex_markup(f, a->title, 1);
	if (a->unit[0] != '\0') {
		fputs(" (", f);
		tex_markup(f, a->unit, 0);
		fputs(")", f);
	}
}

static void
tex_ticks(FILE *f, const char *key, const struct plot_axis *a)
{
	fprintf(f, "    %s={", key);
	for (int k = 0; k < a->nticks; k++)
		cnum_fprintf(f, "%s%.10g", k ? "," : "", a->tick[k] / a->scale);
	fputs("},\n", f);
}

/* the model's own tick labels, so that the figure reads as its PNG */
static void
tex_ticklabels(FILE *f, const char *key, const struct plot_axis *a)
{
	fprintf(f, "    %s={", key);
	for (int k = 0; k < a->nticks; k++) {
		fputs(k ? ",{" : "{", f);
		tex_markup(f, a->ticklabel[k], 0);
		fputs("}", f);
	}
	fputs("},\n", f);
}

static void
tex_style(FILE *f, const struct plot_figure *fig, int style, int line, int markers)
{
	const struct plot_style *st = plot_style_of(style);

	fprintf(f, "c%d", ((style % 8) + 8) % 8);
	cnum_fprintf(f, ", line width=%.3fpt", fig->lw);
	if (!line)
		fputs(", only marks", f);
	if (st->ndash > 0 && line) {
		fputs(", dash pattern=", f);
		for (int k = 0; k < st->ndash; k++)
			cnum_fprintf(f, "%s%s %.3fpt", k ? " " : "", k % 2 ? "off" : "on",
			             st->dash[k] * fig->lw);
	}
	if (markers)
		cnum_fprintf(f, ", mark=*, mark size=%.3fpt, mark options={solid}",
		             1.6 * fig->lw);
	else
		fputs(", mark=none", f);
}

/* Points of a series decimated as plot_draw does: first, lowest, highest
 * and last of each 0.25 pt column, in the units shown. */
static size_t
decimate(const struct plot_panel *p, const struct plot_series *s, double *x, double *y)
{
	size_t m = 0;
	double bx = NAN;
	size_t i0 = 0;

	for (size_t i = 0; i <= s->n; i++) {
		int fin = i < s->n && isfinite(s->x[i]) && isfinite(s->y[i]);
		double col = fin ? floor(plot_axis_pos(&p->xa, s->x[i]) * p->fw / 0.25) : NAN;

		if (fin && !isfinite(col))
			fin = 0, col = NAN;   /* <= 0 on a log axis */

		if (fin && i > i0 && col == bx)
			continue;
		/* the column [i0, i) ends */
		if (i > i0) {
			size_t lo = i0, hi = i0;

			for (size_t j = i0; j < i; j++) {
				if (s->y[j] < s->y[lo])
					lo = j;
				if (s->y[j] > s->y[hi])
					hi = j;
			}
			size_t pick[4] = { i0, lo < hi ? lo : hi, lo < hi ? hi : lo, i - 1 };

			for (int k = 0; k < 4; k++) {
				if (k > 0 && pick[k] == pick[k - 1])
					continue;
				x[m] = s->x[pick[k]] / p->xa.scale;
				y[m++] = s->y[pick[k]] / p->ya.scale;
			}
		}
		if (!fin) {
			if (i < s->n) {
				x[m] = NAN;   /* a break in the line */
				y[m++] = NAN;
			}
			i0 = i + 1;
			bx = NAN;
			continue;
		}
		i0 = i;
		bx = col;
	}
	return m;
}

int
plot_tex_write(struct plot_figure *fig, FILE *tex, FILE *dat, const char *datname,
               const char *provenance, char *msg, size_t n)
{
	double *cx[PLOT_MAX_PANELS * PLOT_MAX_SERIES] = { 0 }, *cy[PLOT_MAX_PANELS * PLOT_MAX_SERIES] = { 0 };
	size_t cn[PLOT_MAX_PANELS * PLOT_MAX_SERIES], rows = 0;
	int ncol = 0, rc = 0, leg_done = 0;

	/* the provenance line, without the preset comment's "; " */
	if (provenance != NULL && strncmp(provenance, "; ", 2) == 0)
		provenance += 2;
	plot_figure_layout(fig, NULL, NULL);
	plot_figure_layout(fig, NULL, NULL);
	/* the data: decimated curves, a pair of columns each */
	for (int k = 0; k < fig->npanels; k++)
		for (int i = 0; i < fig->p[k].ns; i++) {
			const struct plot_series *s = &fig->p[k].s[i];

			cx[ncol] = malloc((4 * s->n + 1) * sizeof(double));
			cy[ncol] = malloc((4 * s->n + 1) * sizeof(double));
			if (cx[ncol] == NULL || cy[ncol] == NULL) {
				rc = -1;
				cnum_snprintf(msg, n, "out of memory");
				goto out;
			}
			cn[ncol] = decimate(&fig->p[k], s, cx[ncol], cy[ncol]);
			if (cn[ncol] > rows)
				rows = cn[ncol];
			ncol++;
		}
	if (provenance != NULL && provenance[0] != '\0')
		fprintf(dat, "# %s\n", provenance);
	fputs("# hybounce plot: curve k is columns xk and yk, in the units of its axes; "
	      "nan pads the shorter curves\n", dat);
	for (int c = 0; c < ncol; c++)
		fprintf(dat, "%sx%d y%d", c ? " " : "", c, c);
	fputc('\n', dat);
	for (size_t r = 0; r < rows; r++) {
		for (int c = 0; c < ncol; c++) {
			if (r < cn[c] && isfinite(cx[c][r]))
				cnum_fprintf(dat, "%s%.9g %.9g", c ? " " : "", cx[c][r], cy[c][r]);
			else
				fprintf(dat, "%snan nan", c ? " " : "");
		}
		fputc('\n', dat);
	}

	/* the picture */
	if (provenance != NULL && provenance[0] != '\0')
		fprintf(tex, "%% %s\n", provenance);
	/* the standalone class where it is installed (texlive-latex-extra),
	 * else article on a page of the figure's size */
	fprintf(tex, "%% Compile with pdflatex in this folder (it reads %s).\n", datname);
	cnum_fprintf(tex, "\\IfFileExists{standalone.cls}{\\documentclass{standalone}}{%%\n"
	             "  \\documentclass{article}\\pagestyle{empty}\n"
	             "  \\setlength{\\hoffset}{-1in}\\setlength{\\voffset}{-1in}"
	             "\\setlength{\\oddsidemargin}{0pt}\\setlength{\\topmargin}{0pt}\n"
	             "  \\setlength{\\headheight}{0pt}\\setlength{\\headsep}{0pt}"
	             "\\setlength{\\parindent}{0pt}\n"
	             "  \\setlength{\\textwidth}{%.2fbp}\\setlength{\\textheight}{%.2fbp}"
	             "\\setlength{\\paperwidth}{%.2fbp}\\setlength{\\paperheight}{%.2fbp}}\n"
	             "\\usepackage{pgfplots}\n"
	             "\\pgfplotsset{compat=1.16}\n", fig->w, fig->h, fig->w, fig->h);
	for (int k = 0; k < 8; k++) {
		const struct plot_style *st = plot_style_of(k);

		fprintf(tex, "\\definecolor{c%d}{RGB}{%d,%d,%d}\n", k, (int)lround(st->r * 255),
		        (int)lround(st->g * 255), (int)lround(st->b * 255));
	}
	fprintf(tex, "\\definecolor{hbshade}{RGB}{%d,%d,%d}\n", (int)lround(plot_shade_rgb[0] * 255),
	        (int)lround(plot_shade_rgb[1] * 255), (int)lround(plot_shade_rgb[2] * 255));
	cnum_fprintf(tex, "\\begin{document}\n\\fontsize{%.1f}{%.1f}\\selectfont\n"
	             "\\begin{tikzpicture}[x=1bp, y=1bp]\n"
	             "\\path (0,0) rectangle (%.2f,%.2f); %% the figure's size\n",
	             fig->font, 1.2 * fig->font, fig->w, -fig->h);
	ncol = 0;
	for (int k = 0; k < fig->npanels; k++) {
		const struct plot_panel *p = &fig->p[k];
		double ylo = p->ya.lo / p->ya.scale, yhi = p->ya.hi / p->ya.scale;

		cnum_fprintf(tex, "\\begin{axis}[at={(%.2fbp,%.2fbp)}, anchor=north west,\n"
		             "    width=%.2fbp, height=%.2fbp, scale only axis,\n"
		             "    xmin=%.10g, xmax=%.10g, ymin=%.10g, ymax=%.10g,\n"
		             "    scaled ticks=false, tick align=inside, axis on top,\n"
		             "    unbounded coords=jump, clip=true,\n"
		             "    every tick label/.append style={font=\\fontsize{%.1f}{%.1f}\\selectfont},\n"
		             "    label style={font=\\fontsize{%.1f}{%.1f}\\selectfont},\n",
		             p->fx, -p->fy, p->fw, p->fh, p->xa.lo / p->xa.scale,
		             p->xa.hi / p->xa.scale, ylo, yhi, fig->font, 1.2 * fig->font,
		             fig->font, 1.2 * fig->font);
		if (p->xa.log)
			fputs("    xmode=log, log basis x=10,\n", tex);
		if (p->ya.log)
			fputs("    ymode=log, log basis y=10,\n", tex);
		if (p->colorbar)   /* a colour legend: its scale on its right */
			fputs("    xtick=\\empty, yticklabel pos=right, ylabel near ticks, "
			      "tick align=outside, ytick style={draw=black},\n", tex);
		else
			tex_ticks(tex, "xtick", &p->xa);
		tex_ticks(tex, "ytick", &p->ya);
		tex_ticklabels(tex, "yticklabels", &p->ya);
		fputs("    ylabel={", tex);
		tex_axis_label(tex, &p->ya);
		fputs("},\n", tex);
		if (p->colorbar) {
			/* no x labels */
		} else if (p->xlabels) {
			tex_ticklabels(tex, "xticklabels", &p->xa);
			fputs("    xlabel={", tex);
			tex_axis_label(tex, &p->xa);
			fputs("},\n", tex);
		} else {
			fputs("    xticklabels={},\n", tex);
		}
		if (!leg_done && fig->nlegend > 0) {
			cnum_fprintf(tex, "    legend style={at={(0,1)}, yshift=%.2fpt, anchor=south west, "
			             "draw=none, fill=none, legend columns=-1,\n"
			             "        /tikz/every even column/.append style={column sep=%.1fpt},\n"
			             "        font=\\fontsize{%.1f}{%.1f}\\selectfont},\n",
			             0.4 * fig->font, fig->font, fig->font, 1.2 * fig->font);
		}
		fputs("]\n", tex);
		for (size_t b = 0; b < p->nband; b++) {
			double a0 = p->band0[b] / p->xa.scale, a1 = p->band1[b] / p->xa.scale;
			/* at least a hairline, as plot_draw.c draws it */
			double wmin = 0.75 * fig->lw / p->fw * (p->xa.hi - p->xa.lo) / p->xa.scale;

			if (a1 - a0 < wmin) {
				double c = 0.5 * (a0 + a1);

				a0 = c - 0.5 * wmin;
				a1 = c + 0.5 * wmin;
			}
			cnum_fprintf(tex, "\\fill[hbshade] (axis cs:%.10g,%.10g) rectangle (axis cs:%.10g,%.10g);\n",
			             a0, ylo, a1, yhi);
		}
		/* a heat map's cells in their colours, as plot_draw.c fills them */
		for (size_t j = 0; j < p->mny; j++)
			for (size_t i = 0; i < p->mnx; i++) {
				double v = p->mv[j * p->mnx + i], rgb[3];

				if (!isfinite(v))
					continue;
				plot_map_colour(p, v, rgb);
				cnum_fprintf(tex, "\\fill[fill={rgb,255:red,%d;green,%d;blue,%d}] "
				             "(axis cs:%.10g,%.10g) rectangle (axis cs:%.10g,%.10g);\n",
				             (int)lround(rgb[0] * 255), (int)lround(rgb[1] * 255),
				             (int)lround(rgb[2] * 255), p->mx[i] / p->xa.scale,
				             p->my[j] / p->ya.scale, p->mx[i + 1] / p->xa.scale,
				             p->my[j + 1] / p->ya.scale);
			}
		for (int i = 0; i < p->ns; i++, ncol++) {
			const struct plot_series *s = &p->s[i];
			int in_legend = !leg_done && s->label[0] != '\0';

			fputs("\\addplot[", tex);
			tex_style(tex, fig, s->style, s->line, s->markers);
			if (!in_legend)
				fputs(", forget plot", tex);
			fprintf(tex, "] table[x=x%d, y=y%d] {%s};\n", ncol, ncol, datname);
			if (in_legend) {
				fputs("\\addlegendentry{", tex);
				tex_markup(tex, s->label, 1);
				fputs("}\n", tex);
			}
		}
		if (!leg_done && fig->nlegend > 0) {
			/* the entries that are no curve of this panel: the shade */
			for (int e = 0; e < fig->nlegend; e++)
				if (fig->legend[e].style < 0) {
					fputs("\\addlegendimage{area legend, fill=hbshade, draw=none}\n"
					      "\\addlegendentry{", tex);
					tex_markup(tex, fig->legend[e].label, 1);
					fputs("}\n", tex);
				}
			leg_done = 1;
		}
		fputs("\\end{axis}\n", tex);
	}
	if (fig->title[0] != '\0') {
		cnum_fprintf(tex, "\\node[anchor=north] at (%.2f,%.2f) {", fig->w / 2, -0.3 * fig->font);
		tex_markup(tex, fig->title, 0);
		fputs("};\n", tex);
	}
	/* the figure's size whatever a label overhangs, as the PNG's */
	cnum_fprintf(tex, "\\pgfresetboundingbox\\path (0,0) rectangle (%.2f,%.2f);\n", fig->w,
	             -fig->h);
	fputs("\\end{tikzpicture}\n\\end{document}\n", tex);
out:
	for (int c = 0; c < PLOT_MAX_PANELS * PLOT_MAX_SERIES; c++) {
		free(cx[c]);
		free(cy[c]);
	}
	return rc;
}
