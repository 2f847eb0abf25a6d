/* glasses.c - `gmat glasses [--markdown]`: the named glasses of the dispersion kit, with their index at the d line,
 * Abbe number, the wavelength range of their formula and its source. */
#include "gmat.h"
#include "generic/kit/dispersion.h"

#include <stdio.h>
#include <string.h>

static void usage_glasses(FILE *f)
{
    fprintf(f, "usage: gmat glasses [--markdown]\n\n"
               "Lists the glasses a file may name (`dielectric { glass BK7 }`, `index glass NAME`): the name, its\n"
               "index n_d at 587.6 nm, its Abbe number V_d = (n_d - 1) / (n_F - n_C), the wavelength range its\n"
               "formula was published for, and the source of the coefficients.\n"
               "  --markdown          a Markdown table instead (docs/reference/format.md)\n"
               "  -h, --help          this text\n");
}

int gmat_glasses(int argc, char **argv)
{
    int n, markdown;
    CliParser p;
    int status = gmat_markdown_option("gmat glasses", argc, argv, usage_glasses, &p, &markdown);
    if (status >= 0)
        return status;
    char **rest = cli_operands(&p, &n);
    if (n > 0)
        return gmat_usage_error("glasses", "unexpected argument '%s'", rest[0]);
    if (markdown)
        printf("| name | glass | n_d | V_d | range (nm) | source |\n| --- | --- | --- | --- | --- | --- |\n");
    for (int i = 0; i < gdispersion_glass_count(); i++) {
        const GGlass *g = gdispersion_glass_at(i);
        double nd = gdispersion_index(&g->formula, 587.56), nf = gdispersion_index(&g->formula, 486.13),
               nc = gdispersion_index(&g->formula, 656.27);
        char name[64];
        snprintf(name, sizeof name, "%s", g->name);
        for (char *s = name; *s; s++) /* the form a file writes */
            *s = *s == ' ' ? '_' : *s;
        if (markdown)
            printf("| `%s` | %s | %.5f | %.2f | %g-%g | %s |\n", name, g->product, nd, (nd - 1) / (nf - nc),
                   g->nm_lo, g->nm_hi, g->source);
        else
            printf("%-13s n_d %.5f  V_d %6.2f  %4g-%-4g nm  %s\n", name, nd, (nd - 1) / (nf - nc), g->nm_lo,
                   g->nm_hi, g->product);
    }
    return fflush(stdout) == 0 ? CLI_OK : CLI_FAILED;
}
