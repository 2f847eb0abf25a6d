/* gcolor.h - the parts of the gcolor tool (examples/gcolor/). */
#ifndef GCOLOR_TOOL_H
#define GCOLOR_TOOL_H

/** `gcolor check MODEL [--step NM]` (check.c): the conformance checks of a colour model, one line per
 * property with its measured worst error and PASS/FAIL; returns the exit status (0 all pass, 1 a failure,
 * 2 a usage error). argv[0] is "check". */
int gcolor_check(int argc, char **argv);

/** `gcolor convert [--colormodel M] [--role reflectance|light] [--samples] LITERAL...` (convert.c): one
 * machine-readable line per colour literal, its XYZ, xy, linear sRGB and brightness in the model and role;
 * returns the exit status (0 every literal converted, 1 one failed, 2 a usage error). argv[0] is "convert". */
int gcolor_convert_command(int argc, char **argv);

#endif
