/* measure.c - what `gprobe eval` and `gprobe report` share: the plan (techniques, sizes, normals) read from
 * their options, the ground truth at the normals, and each technique made, timed and compared with it. */
#include "gprobe.h"

#include <generic/memory.h>

#include <string.h>

/* Parses a comma-separated list of counts (1..4096) into counts (at most max); the number or -1. */
static int parse_count_list(const char *s, int *counts, int max)
{
    int n = 0;
    char buf[512];
    snprintf(buf, sizeof buf, "%s", s);
    for (char *save = NULL, *tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
        if (n >= max) {
            fprintf(stderr, "gprobe: --counts: at most %d counts\n", max);
            return -1;
        }
        if (cli_int("gprobe", "--counts", tok, 1, 4096, &counts[n]) != 0)
            return -1;
        n++;
    }
    if (n == 0)
        fprintf(stderr, "gprobe: --counts: no counts given\n");
    return n > 0 ? n : -1;
}

/* Parses a comma-separated list of method names into use[method_count()]; 0 or -1. */
static int parse_method_list(const char *s, int *use)
{
    char buf[512];
    snprintf(buf, sizeof buf, "%s", s);
    memset(use, 0, sizeof(int) * method_count());
    int any = 0;
    for (char *save = NULL, *tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
        int t = method_find(tok);
        if (t < 0) {
            fprintf(stderr, "gprobe: unknown technique '%s' (expected %s)\n", tok, methods_names);
            return -1;
        }
        use[t] = any = 1;
    }
    if (!any)
        fprintf(stderr, "gprobe: --techniques: none given\n");
    return any ? 0 : -1;
}

void eval_plan_init(EvalPlan *plan, const int *counts, int ncounts)
{
    memset(plan, 0, sizeof *plan);
    plan->normals = 20000;
    memcpy(plan->counts, counts, sizeof(int) * ncounts);
    plan->ncounts = ncounts;
    for (int k = 0; k < method_count(); k++)
        plan->use[k] = !method_is_sh9(k);
}

int eval_plan_option(EvalPlan *plan, int c, const char *v)
{
    switch (c) {
    case PLAN_OPT_NORMALS:
        return cli_int("gprobe", "--normals", v, 1, 10000000, &plan->normals) != 0 ? -1 : 1;
    case PLAN_OPT_FIT:
        return cli_int("gprobe", "--fit-normals", v, 2, 1000000, &plan->fit_normals) != 0 ? -1 : 1;
    case PLAN_OPT_COUNTS:
        return (plan->ncounts = parse_count_list(v, plan->counts, 64)) < 0 ? -1 : 1;
    case PLAN_OPT_TECHNIQUES:
        return parse_method_list(v, plan->use) != 0 ? -1 : 1;
    default:
        return 0;
    }
}

int eval_plan_max_rows(const EvalPlan *plan) { return method_count() * (plan->ncounts + GPROBE_SH_MAX_ORDER); }

int truth_alloc(Truth *t, int m)
{
    t->m = m;
    t->normals = gmem_calloc((size_t)m, sizeof *t->normals);
    t->truth = gmem_calloc((size_t)m * 3, sizeof(double));
    t->approx = gmem_calloc((size_t)m * 3, sizeof(double));
    return t->normals && t->truth && t->approx ? 0 : -1;
}

int truth_compute(Truth *t, const GProbe *p, GError *err)
{
    gprobe_fibonacci(t->m, t->normals);
    return gprobe_irradiance(p, t->normals, t->m, t->truth, err);
}

void truth_free(Truth *t)
{
    gmem_free(t->normals);
    gmem_free(t->truth);
    gmem_free(t->approx);
    memset(t, 0, sizeof *t);
}

void rows_csv(FILE *f, const Row *rows, int n)
{
    fprintf(f, "technique,count,unit,mean_rel,max_rel,mean_norm,max_norm,smape,seconds\n");
    for (int i = 0; i < n; i++) {
        const Method *m = method_get(rows[i].method);
        fprintf(f, "%s,%d,%s,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", m->name, rows[i].count, m->unit, rows[i].e.mean_rel,
                rows[i].e.max_rel, rows[i].e.mean_norm, rows[i].e.max_norm, rows[i].e.smape, rows[i].seconds);
    }
}

/* The progress line of one row: its errors and time, and the irradiance fit's course. */
static void print_row(const Row *row, const GProbeFitReport *rep)
{
    const Method *me = method_get(row->method);
    fprintf(stderr, "\r  %-12s N=%-4d mean %7.3f%%  max %8.3f%%  %7.3f s", me->name, row->count, row->e.mean_rel,
            row->e.max_rel, row->seconds);
    if (me->light == GPROBE_IRRADIANCE) {
        fprintf(stderr, "  (objective %.4g -> %.4g, %d iterations%s", rep->initial, rep->final, rep->iterations,
                rep->converged ? "" : ", iteration limit");
        if (rep->revived)
            fprintf(stderr, ", %d unused lights moved", rep->revived);
        fputc(')', stderr);
    }
    fputc('\n', stderr);
}

/* Makes method `method` at size n into a, times it and compares its irradiance with the truth into row. */
static int eval_one(const GProbe *p, int method, int n, const GProbeOptions *opt, Truth *t, Row *row, Approx *a,
                    int quiet)
{
    GError err;
    GProbeFitReport rep;
    double s = now_seconds();
    if (approx_make(p, method, n, opt, a, &rep, &err) != G_OK) {
        fprintf(stderr, "\ngprobe: %s N=%d: %s\n", method_get(method)->name, n, err.message);
        return -1;
    }
    row->seconds = now_seconds() - s;
    row->method = method;
    row->count = n;
    approx_irradiance(a, t->normals, t->m, t->approx);
    gprobe_compare(t->truth, t->approx, t->m, &row->e);
    if (!quiet)
        print_row(row, &rep);
    return 0;
}

int eval_plan_run(const EvalPlan *plan, const GProbe *p, Truth *truth, int quiet, EvalRowFn fn, void *user)
{
    GProbeOptions opt = probe_options(plan->fit_normals, quiet);
    for (int t = 0; t < method_count(); t++) {
        if (!plan->use[t])
            continue;
        int sizes[64 + GPROBE_SH_MAX_ORDER];
        int ns = method_sizes(t, plan->counts, plan->ncounts, plan->fit_normals, sizes, quiet);
        for (int c = 0; c < ns; c++) {
            Row row;
            Approx a;
            if (eval_one(p, t, sizes[c], &opt, truth, &row, &a, quiet) != 0)
                return -1;
            int rc = fn(user, &row, &a);
            approx_free(&a);
            if (rc != 0)
                return -1;
        }
    }
    return 0;
}
