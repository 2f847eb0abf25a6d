/* export.h - GENERIC_API marks the declarations of the public API: the only symbols libgeneric.so exports
 * (the library is built with -fvisibility=hidden; tests/scripts/exports.sh compares the two lists). */
#ifndef GENERIC_EXPORT_H
#define GENERIC_EXPORT_H

/** Gives a declaration default visibility, so that the shared library exports it and run-time modules
 * resolve it from a program linked with the static library and -rdynamic. */
#if defined(__GNUC__)
#define GENERIC_API __attribute__((visibility("default")))
#else
#define GENERIC_API
#endif

#endif
