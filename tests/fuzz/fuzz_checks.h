/* Invariants of results that more than one C target checks. Each returns what
 * is violated, or NULL; the target reports it with its own context. */
#ifndef POLYMASS_FUZZ_CHECKS_H
#define POLYMASS_FUZZ_CHECKS_H

#include <math.h>
#include <polymass/polymass.h>
#include <stddef.h>
#include <string.h>

static inline int all_finite(const double* values, size_t count) {
    size_t i;
    for (i = 0; i < count; ++i)
        if (!isfinite(values[i])) return 0;
    return 1;
}

/* polymass_inertia_about the point, from properties a call gave: refused
   (INVALID_ARGUMENT) exactly for a non-finite point, or OVERFLOW, the output
   untouched then; otherwise finite, with the parallel-axis trace
   tr I_P = tr I_C + 2 m |C - P|^2. */
static inline const char* inertia_about_violation(const polymass_mass_properties* p,
                                                  const double point[3]) {
    double inertia[9], before[9], distance2 = 0.0, expected, scale;
    int i;
    int32_t status;
    memset(inertia, 0xA5, sizeof inertia);
    memcpy(before, inertia, sizeof before);
    status = polymass_inertia_about(inertia, p, point);
    if (status != POLYMASS_OK && status != POLYMASS_ERROR_OVERFLOW &&
        status != POLYMASS_ERROR_INVALID_ARGUMENT)
        return "polymass_inertia_about: a status it does not document";
    if ((status == POLYMASS_ERROR_INVALID_ARGUMENT) != !all_finite(point, 3))
        return "polymass_inertia_about: INVALID_ARGUMENT is not exactly a non-finite point";
    if (status != POLYMASS_OK)
        return memcmp(inertia, before, sizeof inertia) == 0
                   ? NULL
                   : "polymass_inertia_about: output written on a failure";
    if (!all_finite(inertia, 9)) return "polymass_inertia_about: a non-finite tensor";
    for (i = 0; i < 3; ++i)
        distance2 += (p->center_of_mass[i] - point[i]) * (p->center_of_mass[i] - point[i]);
    expected = p->inertia[0] + p->inertia[4] + p->inertia[8] + 2.0 * p->mass * distance2;
    scale =
        fabs(p->inertia[0]) + fabs(p->inertia[4]) + fabs(p->inertia[8]) + 2.0 * p->mass * distance2;
    if (!(fabs(inertia[0] + inertia[4] + inertia[8] - expected) <= 1e-12 * scale + 1e-300))
        return "polymass_inertia_about: the trace is not the parallel-axis theorem's";
    return NULL;
}

#endif /* POLYMASS_FUZZ_CHECKS_H */
