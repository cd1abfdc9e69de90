/*
 * gw_api.h: the brackets around every public header's declarations.
 * GW_BEGIN_DECLS ... GW_END_DECLS give C++ callers the C symbols (extern "C")
 * and mark what lies between as the library's exported interface (GCC's
 * default visibility: the library is built with -fvisibility=hidden, so
 * everything outside these brackets stays inside libgranwave.so).
 */
#ifndef GW_API_H
#define GW_API_H

#if defined(__GNUC__)
#define GW_VISIBILITY_PUSH_ _Pragma("GCC visibility push(default)")
#define GW_VISIBILITY_POP_ _Pragma("GCC visibility pop")
#else
#define GW_VISIBILITY_PUSH_
#define GW_VISIBILITY_POP_
#endif

#ifdef __cplusplus
#define GW_BEGIN_DECLS extern "C" { GW_VISIBILITY_PUSH_
#define GW_END_DECLS GW_VISIBILITY_POP_ }
#else
#define GW_BEGIN_DECLS GW_VISIBILITY_PUSH_
#define GW_END_DECLS GW_VISIBILITY_POP_
#endif

#endif
