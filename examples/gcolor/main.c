/* gcolor - a colour report: a few colours converted into every registered colour model and back,
 * printed as linear sRGB and CIE XYZ; `gcolor list` names the registered models and `gcolor check MODEL`
 * runs the conformance checks (check.c). Built only on the public API. */
#include "gcolor.h"
#include "../common/cli.h"

#include <generic/builtins.h>
#include <generic/color.h>
#include <generic/plugin.h>
#include <generic/registry.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void usage(FILE *f)
{
    fprintf(f,
            "usage: gcolor [--models LIST] [--rgb R,G,B]... [--plugin FILE.so]...\n"
            "       gcolor list [--plugin FILE.so]...          the registered colour models, one per line\n"
            "       gcolor check MODEL [--step NM] [--plugin FILE.so]...   conformance checks of MODEL\n"
            "       gcolor --help | --version\n"
            "Prints sample colours in every colour model (or the comma-separated LIST): the value the model\n"
            "stores, its brightness, and its conversion back to linear sRGB and CIE 1931 XYZ.\n"
            "  --rgb R,G,B   add a reflectance in linear sRGB to the report (repeatable)\n"
            "  --models LIST only these models, e.g. rgb,spectrum\n"
            "  --plugin FILE.so  load a module first (repeatable; a bare name is searched in the current\n"
            "                directory, then in GENERIC_PLUGIN_PATH, then PREFIX/lib/generic/plugins)\n"
            "  -h, --help    this text\n"
            "  --version     the version\n"
            "Every option value may also be written --option=value.\n"
            "Exit status: 0 when every conversion succeeded, 1 when one failed (it is named on stderr and no value\n"
            "is printed for it), 2 for a usage error such as an unknown option or model.\n");
}

typedef struct Sample {
    const char *name;
    double rgb[3];
    GColorRole role;
} Sample;

/* Prints every sample in one model; a sample whose conversion fails is reported as failed (never with the
 * previous sample's values). Returns 0, or 1 when the model cannot be created or a conversion failed. */
static int report_model(const char *model_name, const Sample *samples, int n)
{
    GError err;
    GColorModel *m = NULL;
    if (gcolormodel_create(model_name, NULL, &m, &err) != G_OK) {
        fprintf(stderr, "gcolor: %s\n", err.message);
        return 1;
    }
    printf("\n== %s (%d values per colour)\n", model_name, m->nvalues);
    GColor c;
    if (gcolor_alloc(&c, m) != G_OK) {
        fprintf(stderr, "gcolor: out of memory\n");
        gcolormodel_destroy(m);
        return 1;
    }
    int failed = 0;
    for (int i = 0; i < n; i++) {
        double rgb[3], xyz[3];
        const char *step = "from sRGB";
        int rc = gcolor_from_rgb(&c, samples[i].rgb, samples[i].role);
        if (rc == G_OK && (rc = gcolor_to_rgb(&c, samples[i].role, rgb)) != G_OK)
            step = "to sRGB";
        if (rc == G_OK && (rc = gcolor_to_xyz(&c, samples[i].role, xyz)) != G_OK)
            step = "to XYZ";
        double bright = rc == G_OK ? gcolor_brightness(&c) : 0.0;
        const char *why = rc != G_OK ? gstatus_string(rc) : NULL;
        if (rc == G_OK && !(isfinite(bright) && isfinite(rgb[0] + rgb[1] + rgb[2]) &&
                            isfinite(xyz[0] + xyz[1] + xyz[2]))) {
            rc = G_ERR_INVALID;
            step = "to sRGB and XYZ";
            why = "the result is not finite (the value is out of the model's range)";
        }
        if (rc != G_OK) {
            printf("  %-18s conversion %s failed\n", samples[i].name, step);
            fprintf(stderr, "gcolor: %s: '%s': the conversion %s failed: %s\n", model_name, samples[i].name, step,
                    why);
            failed = 1;
            continue;
        }
        printf("  %-18s brightness %.4f  -> sRGB %.4f %.4f %.4f  XYZ %.4f %.4f %.4f\n", samples[i].name,
               bright, rgb[0], rgb[1], rgb[2], xyz[0], xyz[1], xyz[2]);
    }
    gcolor_free(&c);
    gcolormodel_destroy(m);
    return failed;
}

/* `gcolor list`: the registered models, one per line. */
static int list_models(int argc, char **argv)
{
    static const struct option longopts[] = {CLI_COMMON_OPTIONS, {0}};
    CliParser p;
    cli_begin(&p, "gcolor list", argc, argv, "h", longopts);
    int c, n;
    while ((c = cli_next(&p)) != -1) {
        if (c == 'h') {
            printf("usage: gcolor list [--plugin FILE.so]...\nThe registered colour models, one per line.\n"
                   CLI_EXIT_STATUS_HELP);
            return CLI_OK;
        }
        if (c == CLI_VERSION)
            return cli_version("gcolor");
        return CLI_USAGE;
    }
    char **rest = cli_operands(&p, &n);
    if (n > 0)
        return cli_usage_error("gcolor list", "unexpected argument '%s'", rest[0]);
    const GTypeInfo *types[64];
    int k = gregistry_list(GKIND_COLORMODEL, types, 64);
    for (int i = 0; i < k && i < 64; i++)
        printf("%s\n", types[i]->name);
    return 0;
}

int main(int argc, char **argv)
{
    GError reg_err;
    if (generic_register_builtins(&reg_err) != G_OK) {
        fprintf(stderr, "%s\n", reg_err.message);
        return 1;
    }
    if (gplugin_load_args(&argc, argv, &reg_err) != G_OK) {
        fprintf(stderr, "gcolor: %s\n", reg_err.message);
        return reg_err.code == G_ERR_INVALID ? 2 : 1;
    }
    if (argc > 1 && strcmp(argv[1], "check") == 0)
        return gcolor_check(argc - 1, argv + 1);
    if (argc > 1 && strcmp(argv[1], "list") == 0)
        return list_models(argc - 1, argv + 1);
    Sample samples[32] = {
        {"white light", {1, 1, 1}, GCOLOR_LIGHT},
        {"grey 18%", {0.18, 0.18, 0.18}, GCOLOR_REFLECTANCE},
        {"red", {0.8, 0.1, 0.1}, GCOLOR_REFLECTANCE},
        {"green", {0.1, 0.7, 0.15}, GCOLOR_REFLECTANCE},
        {"blue", {0.05, 0.1, 0.75}, GCOLOR_REFLECTANCE},
        {"skin", {0.61, 0.42, 0.33}, GCOLOR_REFLECTANCE},
    };
    int n = 6;
    const char *models = NULL;
    static char names[32][48];
    static const struct option longopts[] = {
        CLI_COMMON_OPTIONS, {"models", required_argument, NULL, 'm'}, {"rgb", required_argument, NULL, 'r'}, {0}};
    CliParser p;
    cli_begin(&p, "gcolor", argc, argv, "h", longopts);
    int c;
    while ((c = cli_next(&p)) != -1) {
        if (c == 'h') {
            usage(stdout);
            return CLI_OK;
        } else if (c == CLI_VERSION) {
            return cli_version("gcolor");
        } else if (c == 'm') {
            models = optarg;
        } else if (c == 'r') {
            if (n == 32) {
                fprintf(stderr, "gcolor: at most %d --rgb colours\n", 32 - 6);
                return CLI_USAGE;
            }
            Sample *s = &samples[n];
            char tail;
            if (sscanf(optarg, "%lf,%lf,%lf%c", &s->rgb[0], &s->rgb[1], &s->rgb[2], &tail) != 3 ||
                !isfinite(s->rgb[0]) || !isfinite(s->rgb[1]) || !isfinite(s->rgb[2])) {
                fprintf(stderr, "gcolor: --rgb expects three finite numbers R,G,B, got '%s'\n", optarg);
                return CLI_USAGE;
            }
            snprintf(names[n], sizeof names[n], "rgb %s", optarg);
            s->name = names[n];
            s->role = GCOLOR_REFLECTANCE;
            n++;
        } else {
            return CLI_USAGE;
        }
    }
    int nrest;
    char **rest = cli_operands(&p, &nrest);
    if (nrest > 0) {
        fprintf(stderr, "gcolor: unknown command or argument '%s' (expected list or check; see gcolor --help)\n",
                rest[0]);
        return CLI_USAGE;
    }
    if (models) { /* every name must be a registered model before anything is printed */
        size_t len = strlen(models);
        for (const char *p = models; p <= models + len;) {
            size_t k = strcspn(p, ",");
            char name[128];
            snprintf(name, sizeof name, "%.*s", (int)(k < sizeof name ? k : sizeof name - 1), p);
            if (!k || k >= sizeof name || !gregistry_find(GKIND_COLORMODEL, name)) {
                char names[512];
                gregistry_names(GKIND_COLORMODEL, names, sizeof names);
                fprintf(stderr, "gcolor: --models: unknown colour model '%.*s' (registered: %s)\n", (int)k, p, names);
                return 2;
            }
            p += k + 1;
        }
    }
    printf("Colour report: reflectances are seen under D65 (Y = 1); lights are their own spectrum.\n");
    int failed = 0;
    if (models) {
        size_t len = strlen(models);
        for (const char *p = models; p <= models + len;) {
            size_t k = strcspn(p, ",");
            char name[128];
            snprintf(name, sizeof name, "%.*s", (int)k, p);
            failed |= report_model(name, samples, n);
            p += k + 1;
        }
    } else {
        const GTypeInfo *types[64];
        int k = gregistry_list(GKIND_COLORMODEL, types, 64);
        for (int i = 0; i < k && i < 64; i++)
            failed |= report_model(types[i]->name, samples, n);
    }
    return failed;
}
