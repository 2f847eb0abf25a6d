/* export.h - GENERIC_API marks the declarations of the public API: the only symbols libgeneric.so exports
 * (the library is built with -fvisibility=hidden; tests/scripts/exports.sh compares the two lists).
 *
 * The mark gives default visibility only while the library itself is compiled (GENERIC_BUILD, set by its
 * Makefile). Everywhere else it is empty, so that a file built as a run-time module (with -fvisibility=hidden)
 * keeps its own definitions of public functions local: the lambert constructor inside lambert.so then binds to
 * lambert.so's class, never to the built-in lambert of the program that loads it. */
#ifndef GENERIC_EXPORT_H
#define GENERIC_EXPORT_H

/** Exports a declaration from libgeneric.so (and from a program linked with the static library and -rdynamic,
 * where run-time modules resolve it). */
#if defined(GENERIC_BUILD) && defined(__GNUC__)
#define GENERIC_API __attribute__((visibility("default")))
#else
#define GENERIC_API
#endif

/** Marks a function whose result is a status (G_OK or a negative code): ignoring it is a compile error under
 * -Werror. GCC does not accept a (void) cast to silence it: a call whose status may truly be ignored must say
 * so explicitly (e.g. `if (f() != G_OK) { ... }` with a comment). */
#if defined(__GNUC__)
#define GENERIC_NODISCARD __attribute__((warn_unused_result))
#else
#define GENERIC_NODISCARD
#endif

#endif
