/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * plot_cairo.c - the cairo backend of `hybounce plot`: PNG, PDF and SVG.
 *
 * libcairo (with fontconfig, freetype, pixman, libpng ...) is opened with
 * dlopen(3) the first time a figure is drawn, as the engine does for aubio
 * (src/core/onset_aubio.h): linked into the program, its relocations would
 * be paid at every start of `hybounce --batch`, which draws nothing.  The
 * functions are typed from cairo's own headers.
 *
 * A PNG is written with libpng (which cairo itself uses, opened the same
 * way) rather than cairo_surface_write_to_png: cairo leaves libpng's
 * adaptive row filters and zlib level 6 on, which took 88% of the
 * instructions of a figure (callgrind: 757M of 857M for a 1050 x 1740
 * PNG); no filter and level 3 make the same image in a tenth of the time
 * at about the same size (line art on white compresses well either way),
 * and the PNG says its resolution (pHYs), so that it comes in at its size
 * in inches.
 */
#include <dlfcn.h>
#include <errno.h>
#include <math.h>
#include <pthread.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cairo.h>
#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <png.h>

#include "plot_backend.h"
#include "plot_cairo.h"

#ifndef CAIRO_SONAME
#define CAIRO_SONAME "libcairo.so.2"
#endif

#define CAIRO_FUNCS(X)                                                         \
	X(cairo_image_surface_create) X(cairo_pdf_surface_create_for_stream)     \
	X(cairo_svg_surface_create_for_stream)                                    \
	X(cairo_surface_status) X(cairo_surface_finish) X(cairo_surface_destroy) \
	X(cairo_create) X(cairo_destroy) X(cairo_status) X(cairo_status_to_string) \
	X(cairo_scale) X(cairo_set_source_rgb) X(cairo_set_line_width)           \
	X(cairo_set_dash) X(cairo_move_to) X(cairo_line_to) X(cairo_stroke)      \
	X(cairo_rectangle) X(cairo_fill) X(cairo_arc) X(cairo_new_path)          \
	X(cairo_save) X(cairo_restore) X(cairo_clip) X(cairo_translate)          \
	X(cairo_rotate) X(cairo_select_font_face) X(cairo_set_font_size)         \
	X(cairo_show_text) X(cairo_text_extents) X(cairo_set_line_join)          \
	X(cairo_set_line_cap) X(cairo_pdf_surface_set_metadata)        \
	X(cairo_user_to_device) X(cairo_device_to_user)                       \
	X(cairo_user_to_device_distance) X(cairo_device_to_user_distance)

#ifndef PNG_SONAME
#define PNG_SONAME "libpng16.so.16"
#endif

#define PNG_FUNCS(X)                                                           \
	X(png_create_write_struct) X(png_create_info_struct) X(png_set_write_fn) \
	X(png_set_IHDR) X(png_set_pHYs) X(png_set_filter) X(png_set_compression_level) \
	X(png_write_info) X(png_write_row) X(png_write_end) X(png_destroy_write_struct) \
	X(png_get_error_ptr) X(png_get_io_ptr) X(png_set_text)

struct cairo_api {
#define X(name) __typeof__(&name) name;
	CAIRO_FUNCS(X)
	PNG_FUNCS(X)
#undef X
	__typeof__(&cairo_image_surface_get_data) cairo_image_surface_get_data;
	__typeof__(&cairo_image_surface_get_stride) cairo_image_surface_get_stride;
	__typeof__(&cairo_surface_flush) cairo_surface_flush;
};

static pthread_once_t cairo_once = PTHREAD_ONCE_INIT;
static struct cairo_api C;
static int cairo_loaded;
static char cairo_why[256];

static void
load(void)
{
	void *h = dlopen(CAIRO_SONAME, RTLD_NOW | RTLD_LOCAL);

	if (h == NULL) {
		const char *e = dlerror();

		snprintf(cairo_why, sizeof cairo_why, "%s", e != NULL ? e : CAIRO_SONAME);
		return;
	}
#define X(name)                                                                \
	{                                                                      \
		void *p_ = dlsym(h, #name);                                    \
		if (p_ == NULL) {                                              \
			snprintf(cairo_why, sizeof cairo_why, "%s has no %s", \
			         strncmp(#name, "png_", 4) == 0 ? PNG_SONAME : CAIRO_SONAME, #name); \
			return;                                                \
		}                                                              \
		memcpy(&C.name, &p_, sizeof p_);                               \
	}
	CAIRO_FUNCS(X)
	X(cairo_image_surface_get_data) X(cairo_image_surface_get_stride) X(cairo_surface_flush)
	h = dlopen(PNG_SONAME, RTLD_NOW | RTLD_LOCAL);
	if (h == NULL) {
		const char *e = dlerror();

		snprintf(cairo_why, sizeof cairo_why, "%s", e != NULL ? e : PNG_SONAME);
		return;
	}
	PNG_FUNCS(X)
#undef X
	cairo_loaded = 1;   /* the handle stays open for the life of the process */
}

/* ------------------------------------------------------------------ */
/* the backend */

static void
b_colour(void *ctx, double r, double g, double b)
{
	C.cairo_set_source_rgb(ctx, r, g, b);
}

static void
b_pen(void *ctx, double width, const double *dash, int n)
{
	C.cairo_set_line_width(ctx, width);
	C.cairo_set_dash(ctx, dash, n, 0);
}

static void
b_move_to(void *ctx, double x, double y)
{
	C.cairo_move_to(ctx, x, y);
}

static void
b_line_to(void *ctx, double x, double y)
{
	C.cairo_line_to(ctx, x, y);
}

static void
b_stroke(void *ctx)
{
	C.cairo_stroke(ctx);
}

static void
b_fill_rect(void *ctx, double x, double y, double w, double h)
{
	C.cairo_rectangle(ctx, x, y, w, h);
	C.cairo_fill(ctx);
}

static void
b_fill_dot(void *ctx, double x, double y, double r)
{
	C.cairo_new_path(ctx);
	C.cairo_arc(ctx, x, y, r, 0, 2 * M_PI);
	C.cairo_fill(ctx);
}

static void
b_clip(void *ctx, double x, double y, double w, double h)
{
	C.cairo_save(ctx);
	C.cairo_rectangle(ctx, x, y, w, h);
	C.cairo_clip(ctx);
}

static void
b_unclip(void *ctx)
{
	C.cairo_restore(ctx);
}

static void
b_text(void *ctx, double x, double y, double angle, double size, const char *s)
{
	C.cairo_save(ctx);
	C.cairo_translate(ctx, x, y);
	C.cairo_rotate(ctx, -angle);
	C.cairo_set_font_size(ctx, size);
	C.cairo_move_to(ctx, 0, 0);
	C.cairo_show_text(ctx, s);
	C.cairo_new_path(ctx);
	C.cairo_restore(ctx);
}

static double
b_text_width(void *ctx, const char *s, double size)
{
	cairo_text_extents_t e;

	C.cairo_save(ctx);
	C.cairo_set_font_size(ctx, size);
	C.cairo_text_extents(ctx, s, &e);
	C.cairo_restore(ctx);
	return e.x_advance;
}

static void
b_snap(void *ctx, double *x, double *y, double *width)
{
	double w = *width, z = 0;

	C.cairo_user_to_device(ctx, x, y);
	*x = floor(*x) + 0.5;
	*y = floor(*y) + 0.5;
	C.cairo_device_to_user(ctx, x, y);
	C.cairo_user_to_device_distance(ctx, &w, &z);
	w = fmax(1, round(w));
	z = 0;
	C.cairo_device_to_user_distance(ctx, &w, &z);
	*width = w;
}

/* libpng's callbacks: errors back to write_png by longjmp, data to the
 * caller's stream */
struct png_out {
	jmp_buf jb;
	FILE *f;
	char why[200];
};

static void
png_err(png_structp png, png_const_charp m)
{
	struct png_out *o = C.png_get_error_ptr(png);

	snprintf(o->why, sizeof o->why, "%s", m);
	longjmp(o->jb, 1);
}

static void
png_warn(png_structp png, png_const_charp m)
{
	(void)png;
	(void)m;
}

static void
png_data(png_structp png, png_bytep data, size_t len)
{
	struct png_out *o = C.png_get_io_ptr(png);

	if (fwrite(data, 1, len, o->f) != len) {
		snprintf(o->why, sizeof o->why, "%s", strerror(errno));
		longjmp(o->jb, 1);
	}
}

static void
png_flush_fn(png_structp png)
{
	(void)png;
}

/* The image surface sf (RGB24) as an 8-bit RGB PNG of dpi pixels per inch. */
static int
write_png(cairo_surface_t *sf, int w, int h, double dpi, FILE *f, char *msg, size_t n)
{
	struct png_out o;
	png_structp png;
	png_infop info;
	unsigned char *volatile row = NULL;
	const unsigned char *data;
	int stride;
	png_text text[1];

	C.cairo_surface_flush(sf);
	data = C.cairo_image_surface_get_data(sf);
	stride = C.cairo_image_surface_get_stride(sf);
	memset(&o, 0, sizeof o);
	o.f = f;
	png = C.png_create_write_struct(PNG_LIBPNG_VER_STRING, &o, png_err, png_warn);
	if (png == NULL || data == NULL) {
		snprintf(msg, n, "cannot write the PNG: out of memory");
		return -1;
	}
	info = C.png_create_info_struct(png);
	if (setjmp(o.jb) != 0) {
		C.png_destroy_write_struct(&png, &info);
		free(row);
		snprintf(msg, n, "cannot write the PNG: %s", o.why);
		return -1;
	}
	if (info == NULL)
		png_err(png, "out of memory");
	row = malloc((size_t)w * 3);
	if (row == NULL)
		png_err(png, "out of memory");
	C.png_set_write_fn(png, &o, png_data, png_flush_fn);
	C.png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, 8, PNG_COLOR_TYPE_RGB,
	               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
	C.png_set_pHYs(png, info, (png_uint_32)lround(dpi / 0.0254),
	               (png_uint_32)lround(dpi / 0.0254), PNG_RESOLUTION_METER);
	memset(text, 0, sizeof text);
	text[0].compression = PNG_TEXT_COMPRESSION_NONE;
	text[0].key = (char *)(uintptr_t)"Software";
	text[0].text = (char *)(uintptr_t)"hybounce";
	C.png_set_text(png, info, text, 1);
	C.png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
	C.png_set_compression_level(png, 3);
	C.png_write_info(png, info);
	for (int y = 0; y < h; y++) {
		const uint32_t *px = (const uint32_t *)(const void *)(data + (size_t)y * (size_t)stride);

		for (int x = 0; x < w; x++) {
			row[3 * x] = (unsigned char)(px[x] >> 16);
			row[3 * x + 1] = (unsigned char)(px[x] >> 8);
			row[3 * x + 2] = (unsigned char)px[x];
		}
		C.png_write_row(png, row);
	}
	C.png_write_end(png, info);
	C.png_destroy_write_struct(&png, &info);
	free(row);
	return 0;
}

/* cairo's write callback into the caller's stream */
static cairo_status_t
to_file(void *closure, const unsigned char *data, unsigned int len)
{
	return fwrite(data, 1, len, closure) == len ? CAIRO_STATUS_SUCCESS
	                                             : CAIRO_STATUS_WRITE_ERROR;
}

int
plot_cairo_write(struct plot_figure *f, enum plot_format fmt, double dpi, FILE *out,
                 char *msg, size_t n)
{
	cairo_surface_t *sf;
	cairo_t *cr;
	struct plot_backend b;
	int rc = 0;

	pthread_once(&cairo_once, load);
	if (!cairo_loaded) {
		snprintf(msg, n, "drawing a figure needs libcairo (%s), which cannot be loaded: %s; "
		         "expected the Debian package libcairo2 (make deps installs it)",
		         CAIRO_SONAME, cairo_why);
		return -1;
	}
	switch (fmt) {
	case PLOT_PNG:
		sf = C.cairo_image_surface_create(CAIRO_FORMAT_RGB24, (int)lround(f->w * dpi / 72),
		                                  (int)lround(f->h * dpi / 72));
		break;
	case PLOT_PDF:
		sf = C.cairo_pdf_surface_create_for_stream(to_file, out, f->w, f->h);
		break;
	default:
		sf = C.cairo_svg_surface_create_for_stream(to_file, out, f->w, f->h);
		break;
	}
	if (C.cairo_surface_status(sf) != CAIRO_STATUS_SUCCESS) {
		snprintf(msg, n, "cairo: %s", C.cairo_status_to_string(C.cairo_surface_status(sf)));
		C.cairo_surface_destroy(sf);
		return -1;
	}
	if (fmt == PLOT_PDF)
		C.cairo_pdf_surface_set_metadata(sf, CAIRO_PDF_METADATA_CREATOR, "hybounce");
	cr = C.cairo_create(sf);
	if (fmt == PLOT_PNG)
		C.cairo_scale(cr, dpi / 72, dpi / 72);
	C.cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
	                         CAIRO_FONT_WEIGHT_NORMAL);
	C.cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
	C.cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
	b = (struct plot_backend){
		.ctx = cr, .colour = b_colour, .pen = b_pen, .move_to = b_move_to,
		.line_to = b_line_to, .stroke = b_stroke, .fill_rect = b_fill_rect,
		.fill_dot = b_fill_dot, .clip = b_clip, .unclip = b_unclip, .text = b_text,
		.text_width = b_text_width, .snap = fmt == PLOT_PNG ? b_snap : NULL,
	};
	/* twice: the margins depend on the tick labels, the ticks on the frames */
	plot_figure_layout(f, b_text_width, cr);
	plot_figure_layout(f, b_text_width, cr);
	plot_draw(f, &b);
	if (C.cairo_status(cr) != CAIRO_STATUS_SUCCESS) {
		snprintf(msg, n, "cairo: %s", C.cairo_status_to_string(C.cairo_status(cr)));
		rc = -1;
	}
	C.cairo_destroy(cr);
	if (rc == 0 && fmt == PLOT_PNG)
		rc = write_png(sf, (int)lround(f->w * dpi / 72), (int)lround(f->h * dpi / 72), dpi,
		               out, msg, n);
	C.cairo_surface_finish(sf);
	if (rc == 0 && C.cairo_surface_status(sf) != CAIRO_STATUS_SUCCESS) {
		snprintf(msg, n, "cairo: %s", C.cairo_status_to_string(C.cairo_surface_status(sf)));
		rc = -1;
	}
	C.cairo_surface_destroy(sf);
	return rc;
}
