/* alias_table.h - Walker's alias method in Vose's construction (alias_table.c): a choice among n outcomes of given
 * probabilities in constant time from one uniform number, shared by the light tables (light_pick.h, emissive.h). */
#ifndef GTRACE_ALIAS_TABLE_H
#define GTRACE_ALIAS_TABLE_H

/** Fills q[0..n) and alias[0..n) (n >= 1) for the probabilities prob[0..n) (summing to 1): slot i keeps outcome i
 * with probability q[i], else gives alias[i]. G_OK or G_ERR_NOMEM (its work lists). */
int alias_table_build(const double *prob, int n, double *q, int *alias);
/** The outcome of the table (q, alias, n >= 1) for u in [0, 1); into *u_rest (may be NULL) what is left of u,
 * rescaled to [0, 1) and independent of the outcome (u itself when n is 1). */
int alias_table_pick(const double *q, const int *alias, int n, double u, double *u_rest);

#endif
