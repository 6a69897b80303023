/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * export.h - how every public header of libhybounce opens and closes.
 *
 * Each public header puts its declarations between HB_BEGIN_DECLS and
 * HB_END_DECLS, which give them
 *
 *  - C linkage when the header is read by a C++ compiler (extern "C"), and
 *  - default visibility, i.e. exported from libhybounce.so.  The library is
 *    compiled with -fvisibility=hidden, so the functions and objects that
 *    no public header declares (the engine's internals) are not exported:
 *    nm -D on the library lists the public API and nothing else.
 *
 * A definition in src/core/ takes the visibility of its declaration here,
 * so no function needs a macro of its own.  Outside GCC and Clang the
 * visibility part is empty.
 */
#ifndef HB_EXPORT_H
#define HB_EXPORT_H

#if defined(__GNUC__) && __GNUC__ >= 4
#define HB_VISIBILITY_PUSH _Pragma("GCC visibility push(default)")
#define HB_VISIBILITY_POP  _Pragma("GCC visibility pop")
#else
#define HB_VISIBILITY_PUSH
#define HB_VISIBILITY_POP
#endif

#ifdef __cplusplus
#define HB_BEGIN_DECLS HB_VISIBILITY_PUSH extern "C" {
#define HB_END_DECLS   } HB_VISIBILITY_POP
#else
#define HB_BEGIN_DECLS HB_VISIBILITY_PUSH
#define HB_END_DECLS   HB_VISIBILITY_POP
#endif

#endif
