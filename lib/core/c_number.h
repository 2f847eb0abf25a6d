/* c_number.h - numbers in the C locale, for every reader of text files in lib/ (private to lib/). */
#ifndef GENERIC_LIB_C_NUMBER_H
#define GENERIC_LIB_C_NUMBER_H

/** strtod in the C locale, whatever the program's LC_NUMERIC (files always use '.' as decimal point). */
double gnum_strtod(const char *s, char **end);

#endif
