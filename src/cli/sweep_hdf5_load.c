/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_hdf5_load.c - libhdf5 for `hybounce sweep --format hdf5`
 * (sweep_hdf5.c), opened with dlopen(3) when a sweep first asks for it, as
 * plot_cairo.c does cairo: linked into the program, its relocations would
 * be paid at every start of `hybounce --batch`.  Its functions are typed
 * from its own headers (sweep_hdf5_api.h).
 */
#include <dlfcn.h>
#include <pthread.h>
#include <stdio.h>
#include <string.h>

#include <hdf5.h>

#include "hybounce/status.h"
#include "sweep_hdf5.h"
#include "sweep_hdf5_api.h"

#ifndef HDF5_SONAME
#define HDF5_SONAME "libhdf5_serial.so.103"
#endif

struct h5_api h5api;

static pthread_once_t h5_once = PTHREAD_ONCE_INIT;
static int h5_loaded;
static char h5_why[256];

static void
load(void)
{
	void *h = dlopen(HDF5_SONAME, RTLD_NOW | RTLD_LOCAL);

	if (h == NULL) {
		const char *e = dlerror();

		snprintf(h5_why, sizeof h5_why, "%s", e != NULL ? e : HDF5_SONAME);
		return;
	}
#define X(name)                                                                \
	{                                                                      \
		void *p_ = dlsym(h, #name);                                    \
		if (p_ == NULL) {                                              \
			snprintf(h5_why, sizeof h5_why, "%s has no %s", HDF5_SONAME, #name); \
			return;                                                \
		}                                                              \
		memcpy(&h5api.name, &p_, sizeof p_);                               \
	}
	H5_FUNCS(X)
#undef X
	h5api.native_double = dlsym(h, "H5T_NATIVE_DOUBLE_g");
	h5api.native_int64 = dlsym(h, "H5T_NATIVE_INT64_g");
	h5api.c_s1 = dlsym(h, "H5T_C_S1_g");
	h5api.dataset_create = dlsym(h, "H5P_CLS_DATASET_CREATE_ID_g");
	if (h5api.native_double == NULL || h5api.native_int64 == NULL || h5api.c_s1 == NULL ||
	    h5api.dataset_create == NULL) {
		snprintf(h5_why, sizeof h5_why, "%s lacks its type globals", HDF5_SONAME);
		return;
	}
	if (h5api.H5open() < 0) {
		snprintf(h5_why, sizeof h5_why, "%s: H5open failed", HDF5_SONAME);
		return;
	}
	h5api.H5Eset_auto2(H5E_DEFAULT, NULL, NULL);   /* errors come back as messages */
	h5_loaded = 1;   /* the handle stays open for the life of the process */
}

int
sweep_hdf5_available(char *msg, size_t n)
{
	pthread_once(&h5_once, load);
	if (h5_loaded)
		return HB_OK;
	return hb_status_set(msg, n, HB_EINVAL, "--format hdf5: libhdf5 cannot be loaded (%s); "
	                     "install it (Debian: libhdf5-103-1, with libhdf5-dev) or use "
	                     "--format csv", h5_why);
}
