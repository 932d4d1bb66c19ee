/* What the tests of the intersection check (test_intersections.c: faces
   that cross or touch; test_nesting.c: how shells lie inside each other)
   share. Every case is also tried far from the origin and at tiny and huge
   scales: the verdicts come from exact predicates, so they must not change. */
#ifndef POLYMASS_OVERLAP_CASES_H
#define POLYMASS_OVERLAP_CASES_H

#include "test_support.h"

/* The default options check intersections; UNCHECKED skips it by name. */
#define CHECKED 0u
#define UNCHECKED (POLYMASS_OPTION_SKIP_INTERSECTION_CHECK)

/* Where each case is also tried. */
extern const pm_placement placements[];
extern const size_t placement_count;

/* An axis-aligned box (quads, or triangulated), inside out on request. */
void box(pm_mesh* m, double x0, double y0, double z0, double x1, double y1, double z1,
         int triangulate, int inside_out);
/* An octahedron of the given centre and radius (a cavity when inside_out). */
void octahedron(pm_mesh* m, const double c[3], double r, int inside_out);

/* Computes with and without the intersection check; returns the checked
   status. The unchecked status is `unchecked`. */
int32_t verdicts(const pm_mesh* m, int32_t* unchecked, uint32_t* warnings, double* volume);

/* polymass_mesh_shells of the mesh made with the flags: the first
   min(capacity, count) shells and their count. */
int32_t shell_list(polymass_shell* shells, uint64_t capacity, uint64_t* count,
                   polymass_context* ctx, const pm_mesh* m, uint32_t flags);

typedef struct expectation {
    int32_t checked;   /* status with the intersection check */
    int32_t unchecked; /* status without */
    uint32_t warnings; /* with the check, when it passes */
    double volume;     /* with the check, when it passes (before placement) */
} expectation;

/* Crossing: refused with the check, accepted without. */
extern const expectation overlap;

/* The expectation at every placement, the volume scaled with it. */
void expect_everywhere(const char* what, const pm_mesh* original, expectation e);

#endif
