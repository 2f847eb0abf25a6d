/* metals.c - `gmat metals`: the measured metals and compounds that `conductor { metal NAME }` knows
 * (generic/kit/metals.h), with what each is, its measured range and its source; --markdown writes the reference page
 * docs/reference/metals.md. */
#include "gmat.h"
#include "../common/cli.h"

#include <generic/kit/fresnel.h>
#include <generic/kit/metals.h>

#include <stdio.h>

static void metals_usage(FILE *f)
{
    fprintf(f, "usage: gmat metals [--markdown]\n\n"
               "Lists the measured optical constants `conductor { metal NAME }` takes: each name, what it is, its\n"
               "normal-incidence reflectance at 450, 550 and 650 nm, the measured range and the source.\n"
               "  --markdown          the reference page (docs/reference/metals.md)\n"
               "  -h, --help          this text\n"
               "  --version           the version\n"
            CLI_EXIT_STATUS_HELP);
}

static double r0(int i, double nm) { return goptics_fresnel_conductor(1.0, gmetal_eta_at(i, nm), gmetal_k_at(i, nm)); }

int gmat_metals(int argc, char **argv)
{
    int n, markdown;
    CliParser p;
    int status = gmat_markdown_option("gmat metals", argc, argv, metals_usage, &p, &markdown);
    if (status >= 0)
        return status;
    char **rest = cli_operands(&p, &n);
    if (n > 0)
        return gmat_usage_error("metals", "unexpected argument '%s'", rest[0]);
    if (markdown)
        printf("# Measured metals\n\n"
               "The names `conductor { metal NAME }` takes (`gmat metals` lists them). Each is a published measurement"
               "\nof the complex refractive index n + i k from the refractiveindex.info database (public domain, CC0"
               " 1.0),\ninterpolated every 5 nm from 360 to 830 nm and held constant beyond the measured range;"
               " `scripts/gen_metals.py`\nwrites the table (lib/kit/metal_table.c) from the database's files. R(0) is"
               " the normal-incidence\nreflectance ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2).\n\n"
               "![Every metal below at roughness 0.15, in spectrum, by gmat swatch (scripts/docs_images.sh)]"
               "(../images/metals.png)\n\n"
               "| name | material | R(0) at 450, 550, 650 nm | measured (nm) | source |\n"
               "| --- | --- | --- | --- | --- |\n");
    for (int i = 0; i < gmetal_count(); i++) {
        GMetalInfo m;
        if (gmetal_info(i, &m) != G_OK)
            return CLI_FAILED;
        if (markdown)
            printf("| `%s` | %s | %.3f, %.3f, %.3f | %.0f..%.0f | %s |\n", m.name, m.description, r0(i, 450),
                   r0(i, 550), r0(i, 650), m.min_nm, m.max_nm, m.source);
        else
            printf("%-7s %-42s R(0) %.3f %.3f %.3f  %5.0f..%.0f nm  %s\n", m.name, m.description, r0(i, 450),
                   r0(i, 550), r0(i, 650), m.min_nm, m.max_nm, m.source);
    }
    return fflush(stdout) == 0 ? CLI_OK : CLI_FAILED;
}
