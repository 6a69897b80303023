/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_hdf5_api.h - the functions of libhdf5 that sweep_hdf5.c calls, as
 * pointers that sweep_hdf5_load.c fills with dlsym once
 * sweep_hdf5_available has returned HB_OK.
 */
#ifndef HYBOUNCE_CLI_SWEEP_HDF5_API_H
#define HYBOUNCE_CLI_SWEEP_HDF5_API_H

#include <hdf5.h>

#define H5_FUNCS(X)                                                            \
	X(H5open) X(H5Eset_auto2) X(H5Fcreate) X(H5Fclose) X(H5Screate_simple)   \
	X(H5Screate) X(H5Sclose) X(H5Pcreate) X(H5Pset_chunk) X(H5Pset_deflate) \
	X(H5Pset_shuffle) X(H5Pclose) X(H5Tcreate) X(H5Tinsert) X(H5Tcopy)      \
	X(H5Tset_size) X(H5Tset_cset) X(H5Tclose) X(H5Dcreate2) X(H5Dset_extent) \
	X(H5Dget_space) X(H5Sselect_hyperslab) X(H5Dwrite) X(H5Dclose)          \
	X(H5Acreate2) X(H5Awrite) X(H5Aclose)

struct h5_api {
#define X(name) __typeof__(&name) name;
	H5_FUNCS(X)
#undef X
	hid_t *native_double, *native_int64, *c_s1, *dataset_create;
};

extern struct h5_api h5api;

#endif
