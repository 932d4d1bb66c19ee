/* Mass properties of an aluminium L-bracket with libpolymass.
 *
 * The bracket is an L-shaped profile (a non-convex hexagon, 40 x 30 mm with
 * 10 mm thick legs) extruded 20 mm along z: two hexagonal caps and six quads.
 * Lengths are in metres and the density in kg/m^3, so the mass is in kg and
 * the inertia in kg*m^2.
 *
 * Two ways in: an engine's load path makes one call
 * (polymass_mass_properties_compute: surface, options and mass in, properties
 * out); a tool that asks more than one question analyses the surface once
 * (polymass_mesh_create) and asks the handle (its verdict, what the checks
 * found, the properties for any density or mass, the inertia about any point).
 *
 *   cc -std=c99 mass_properties.c $(pkg-config --cflags --libs polymass)
 */
#include <polymass/polymass.h>
#include <stdio.h>

/* Prints what failed and why; returns nonzero if status is an error. */
static int failed(int32_t status, const polymass_context* context, const char* what) {
    if (status == POLYMASS_OK) return 0;
    fprintf(stderr, "%s failed: %s", what, polymass_status_string(status));
    if (context != NULL) fprintf(stderr, " (%s)", polymass_context_message(context));
    fprintf(stderr, "\n");
    return 1;
}

static void print_matrix(const char* name, const double m[9]) {
    int row;
    for (row = 0; row < 3; ++row) {
        printf("%-16s [% .6e % .6e % .6e]\n", row == 0 ? name : "", m[3 * row], m[3 * row + 1],
               m[3 * row + 2]);
    }
}

int main(void) {
    /* The L profile, counter-clockwise seen from +z, at z = 0 (vertices 0-5)
       and at z = 0.02 (vertices 6-11). */
    static const double positions[12][3] = {
        {0.00, 0.00, 0.00}, /* 0 */
        {0.04, 0.00, 0.00}, /* 1 */
        {0.04, 0.01, 0.00}, /* 2 */
        {0.01, 0.01, 0.00}, /* 3: the inner (reflex) corner */
        {0.01, 0.03, 0.00}, /* 4 */
        {0.00, 0.03, 0.00}, /* 5 */
        {0.00, 0.00, 0.02}, /* 6 */
        {0.04, 0.00, 0.02}, /* 7 */
        {0.04, 0.01, 0.02}, /* 8 */
        {0.01, 0.01, 0.02}, /* 9 */
        {0.01, 0.03, 0.02}, /* 10 */
        {0.00, 0.03, 0.02}, /* 11 */
    };
    /* Faces are counter-clockwise seen from outside: the bottom cap is the
       profile reversed, the top cap is the profile, then one quad per edge. */
    static const uint32_t indices[] = {
        5, 4, 3,  2,  1,  0,  /* bottom cap (z = 0), normal -z */
        6, 7, 8,  9,  10, 11, /* top cap (z = 0.02), normal +z */
        0, 1, 7,  6,          /* side on edge 0-1 */
        1, 2, 8,  7,          /* side on edge 1-2 */
        2, 3, 9,  8,          /* side on edge 2-3 */
        3, 4, 10, 9,          /* side on edge 3-4 */
        4, 5, 11, 10,         /* side on edge 4-5 */
        5, 0, 6,  11,         /* side on edge 5-0 */
    };
    static const uint32_t face_sizes[] = {6, 6, 4, 4, 4, 4, 4, 4};

    polymass_context* context = NULL;
    /* Every struct starts with struct_size = sizeof(the struct): the
       initialisers set it and the defaults (here: unit density). */
    polymass_mesh_desc mesh = POLYMASS_MESH_DESC_INIT;
    polymass_mass_desc body = POLYMASS_MASS_DESC_INIT;
    polymass_mass_properties p = POLYMASS_MASS_PROPERTIES_INIT;
    polymass_mesh* analysed = NULL;
    polymass_diagnostics found = POLYMASS_DIAGNOSTICS_INIT;
    polymass_mass_desc kilogram = POLYMASS_MASS_DESC_INIT;
    polymass_mass_properties of_1kg = POLYMASS_MASS_PROPERTIES_INIT;
    /* The centre of the long leg's end face, where a fixture holds it. */
    static const double fixture[3] = {0.04, 0.005, 0.01};
    double inertia_at_fixture[9];
    int32_t status;
    int i;

    /* The library loaded at run time must have the major version compiled against. */
    if (polymass_version() / 10000 != POLYMASS_VERSION_MAJOR) {
        fprintf(stderr, "libpolymass %s is not compatible with the header (%s)\n",
                polymass_version_string(), POLYMASS_VERSION_STRING);
        return 1;
    }
    printf("libpolymass %s\n", polymass_version_string());

    status = polymass_context_create(&context, NULL); /* NULL: malloc */
    if (failed(status, NULL, "polymass_context_create")) return 1;

    mesh.position_type = POLYMASS_POSITION_FLOAT64;
    mesh.positions = positions;
    mesh.vertex_count = 12;
    mesh.position_stride = 0; /* packed x, y, z */
    mesh.index_type = POLYMASS_INDEX_UINT32;
    mesh.indices = indices;
    mesh.index_count = sizeof indices / sizeof indices[0];
    mesh.face_sizes = face_sizes;
    mesh.face_count = sizeof face_sizes / sizeof face_sizes[0];

    body.mass_mode = POLYMASS_MASS_FROM_DENSITY;
    body.density = 2700.0; /* aluminium, kg/m^3 */

    /* One call: no provenance wanted (NULL), the default options (NULL: every
       check, the exact solid or an error). */
    status = polymass_mass_properties_compute(&p, NULL, context, &mesh, NULL, &body);
    if (failed(status, context, "polymass_mass_properties_compute")) {
        polymass_context_destroy(context);
        return 1;
    }

    printf("volume           %.6g m^3\n", p.volume);
    printf("mass             %.6g kg\n", p.mass);
    printf("surface area     %.6g m^2\n", p.surface_area);
    printf("centre of mass   (%.6g, %.6g, %.6g) m\n", p.center_of_mass[0], p.center_of_mass[1],
           p.center_of_mass[2]);
    print_matrix("inertia (COM)", p.inertia); /* kg*m^2, row-major */
    for (i = 0; i < 3; ++i) {
        /* Column i of the row-major rotation is the axis of principal moment i. */
        printf("principal %d      %.6e kg*m^2 about (% .4f, % .4f, % .4f)\n", i + 1,
               p.principal_moments[i], p.principal_axes[i], p.principal_axes[3 + i],
               p.principal_axes[6 + i]);
    }
    if (p.warnings != 0) printf("warnings         0x%x\n", (unsigned)p.warnings);

    /* One analysis, many questions. polymass_mesh_create returns the mesh's
       status, and gives a mesh even when the surface is refused, so that the
       caller can read why (polymass_mesh_message, polymass_mesh_diagnostics). */
    status = polymass_mesh_create(&analysed, context, &mesh, NULL);
    if (analysed != NULL) status = polymass_mesh_diagnostics(&found, context, analysed);
    if (status == POLYMASS_OK) {
        printf("analysis         %s: %llu faces, %llu edges, %llu shell(s)\n",
               polymass_status_string(polymass_mesh_status(analysed)),
               (unsigned long long)found.face_count, (unsigned long long)found.edge_count,
               (unsigned long long)found.shell_count);
        /* The same part weighed at 1 kg, and its inertia about the fixture:
           no second pass over the faces. */
        kilogram.mass_mode = POLYMASS_MASS_FROM_TOTAL;
        kilogram.mass = 1.0;
        status = polymass_mesh_mass_properties(&of_1kg, context, analysed, &kilogram);
    }
    if (status == POLYMASS_OK)
        status = polymass_inertia_about(inertia_at_fixture, &of_1kg, fixture);
    polymass_mesh_destroy(analysed); /* NULL is accepted */
    if (failed(status, context, "the questions to the mesh")) {
        polymass_context_destroy(context);
        return 1;
    }
    printf("as 1 kg: density %.6g kg/m^3\n", of_1kg.density);
    print_matrix("inertia (grip)", inertia_at_fixture);

    polymass_context_destroy(context);
    return 0;
}
