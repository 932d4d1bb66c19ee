/* libFuzzer target: arbitrary bytes as a program over the moments API
 * (polymass_moments_*): bodies made from a cube mesh (polymass_mesh_create,
 * polymass_mesh_moments) or written raw, then composed, and their mass
 * properties taken, with the inertia about a point.
 *
 * Input format (bytes past the end read as 0):
 *   repeated until the input ends, one operation per record:
 *     1 byte   operation (% 8) and slots: bits 0-2 the operation, bits 3-4
 *              the target slot, bits 5-6 the operand slot (4 slots, all
 *              starting as the unit cube's moments)
 *     then the operation's arguments, raw doubles (8 bytes each):
 *       0 compute     3 scale factors and 3 offsets of the cube's vertices
 *                     (polymass_mesh_create + polymass_mesh_moments)
 *       1 raw         the 19 doubles of a polymass_moments (reference to
 *                     second, then the 5 error bounds), then a flags byte
 *       2 add, 3 subtract   target = target op operand (no arguments)
 *       4 transform   9 doubles of a rotation (nearly orthonormal or not)
 *                     and 3 of a translation
 *       5 scale       3 factors
 *       6 weight      a mode byte and a value
 *       7 mass properties   a mode byte, a value and a point (3 doubles):
 *                     polymass_moments_mass_properties, then
 *                     polymass_inertia_about the point
 *
 * Invariants: every status is one the API documents for the call (never
 * POLYMASS_ERROR_INTERNAL) and the message is "" exactly after a success;
 * after a failure the output is untouched; after a success the moments'
 * numbers are finite, and mass properties are finite with a positive volume
 * and mass, ascending principal moments and orthonormal axes; the inertia
 * about a point is refused (INVALID_ARGUMENT) exactly when the point is not
 * finite, and is finite when given, with a trace that is the centre of mass's
 * plus 2 m |d|^2 (the parallel-axis theorem). */
#include <math.h>
#include <polymass/polymass.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "fuzz_checks.h"
#include "fuzz_input.h"

static const char* current_call = "";

static void fail(int line, const char* what, int32_t status, const polymass_context* context) {
    fprintf(stderr, "\nfuzz_moments.c:%d: invariant violated after %s: %s\n  status %d (%s), %s\n",
            line, current_call, what, (int)status, polymass_status_string(status),
            polymass_context_message(context));
    fflush(stderr);
    __builtin_trap();
}

#define CHECK(condition, status, context) \
    ((condition) ? (void)0 : fail(__LINE__, #condition, status, context))

/* After a call writing *out (size bytes) from a copy `before`. */
static void check_call(int32_t status, const void* out, const void* before, size_t size,
                       const polymass_context* context) {
    const char* message = polymass_context_message(context);
    CHECK(status != POLYMASS_ERROR_INTERNAL, status, context);
    CHECK(strcmp(polymass_status_string(status), "unknown status") != 0, status, context);
    CHECK((status == POLYMASS_OK) == (message[0] == '\0'), status, context);
    if (status != POLYMASS_OK) CHECK(memcmp(out, before, size) == 0, status, context);
}

static void check_moments(int32_t status, const polymass_moments* m,
                          const polymass_context* context) {
    if (status != POLYMASS_OK) return;
    CHECK(m->struct_size == sizeof *m, status, context);
    CHECK(all_finite(m->reference, 3) && isfinite(m->volume) && isfinite(m->mass) &&
              all_finite(m->first, 3) && all_finite(m->second, 6),
          status, context);
}

static void check_properties(int32_t status, const polymass_mass_properties* p,
                             const polymass_context* context) {
    int i, j, k;
    if (status != POLYMASS_OK) return;
    CHECK(p->volume > 0.0 && p->mass > 0.0 && p->density > 0.0, status, context);
    CHECK(all_finite(p->center_of_mass, 3) && all_finite(p->inertia, 9) &&
              all_finite(p->principal_moments, 3) && all_finite(p->principal_axes, 9),
          status, context);
    CHECK(p->principal_moments[0] <= p->principal_moments[1] &&
              p->principal_moments[1] <= p->principal_moments[2],
          status, context);
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) {
            double dot = 0.0;
            for (k = 0; k < 3; ++k)
                dot += p->principal_axes[3 * k + i] * p->principal_axes[3 * k + j];
            CHECK(fabs(dot - (i == j)) <= 1e-9, status, context);
        }
}

/* The unit cube (vertex v at x = bit 0, y = bit 1, z = bit 2 of v; quads
   counter-clockwise seen from outside), each coordinate c as scale * c +
   offset. */
static int32_t cube_moments(polymass_moments* out, polymass_context* context, const double scale[3],
                            const double offset[3]) {
    static const uint32_t quads[24] = {0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4,
                                       2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5};
    static const uint32_t sizes[6] = {4, 4, 4, 4, 4, 4};
    double positions[24];
    polymass_mesh_desc desc;
    int v, k;
    for (v = 0; v < 8; ++v)
        for (k = 0; k < 3; ++k) positions[3 * v + k] = scale[k] * ((v >> k) & 1) + offset[k];
    memset(&desc, 0, sizeof desc);
    desc.struct_size = sizeof desc;
    desc.position_type = POLYMASS_POSITION_FLOAT64;
    desc.positions = positions;
    desc.vertex_count = 8;
    desc.index_type = POLYMASS_INDEX_UINT32;
    desc.indices = quads;
    desc.index_count = 24;
    desc.face_sizes = sizes;
    desc.face_count = 6;
    /* One analysis (default options: every check); a refused cube's
       polymass_mesh_moments gives the mesh's status and message. */
    {
        polymass_mesh* mesh = NULL;
        int32_t status = polymass_mesh_create(&mesh, context, &desc, NULL);
        if (mesh != NULL) status = polymass_mesh_moments(out, context, mesh);
        polymass_mesh_destroy(mesh);
        return status;
    }
}

static polymass_mass_desc take_mass(reader* r) {
    polymass_mass_desc mass;
    memset(&mass, 0, sizeof mass);
    mass.struct_size = sizeof mass;
    mass.mass_mode = take_u8(r) % 3; /* 2: unknown, refused */
    mass.density = mass.mass = take_double(r);
    return mass;
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const double unit[3] = {1.0, 1.0, 1.0}, zero[3] = {0.0, 0.0, 0.0};
    reader r = {data, size, 0};
    polymass_context* context = NULL;
    polymass_moments slots[4], before;
    int32_t status;
    int i, operations = 0;
    if (polymass_context_create(&context, NULL) != POLYMASS_OK) __builtin_trap();
    memset(&slots[0], 0, sizeof slots[0]);
    slots[0].struct_size = sizeof slots[0];
    current_call = "the unit cube's moments";
    status = cube_moments(&slots[0], context, unit, zero);
    CHECK(status == POLYMASS_OK, status, context);
    for (i = 1; i < 4; ++i) slots[i] = slots[0];

    while (r.at < r.size && operations++ < 64) {
        const uint8_t code = take_u8(&r);
        polymass_moments* target = &slots[(code >> 3) & 3];
        const polymass_moments* operand = &slots[(code >> 5) & 3];
        double values[12];
        before = *target;
        switch (code & 7) {
            case 0:
                current_call = "a cube's moments";
                for (i = 0; i < 6; ++i) values[i] = take_double(&r);
                status = cube_moments(target, context, values, values + 3);
                break;
            case 1:
                current_call = "raw moments";
                take(&r, (uint8_t*)target + offsetof(polymass_moments, reference),
                     sizeof *target - offsetof(polymass_moments, reference));
                target->flags = take_u8(&r) & 3;
                continue;
            case 2:
                current_call = "polymass_moments_add";
                status = polymass_moments_add(target, context, target, operand);
                break;
            case 3:
                current_call = "polymass_moments_subtract";
                status = polymass_moments_subtract(target, context, target, operand);
                break;
            case 4:
                current_call = "polymass_moments_transform";
                for (i = 0; i < 12; ++i) values[i] = take_double(&r);
                status = polymass_moments_transform(target, context, target, values, values + 9);
                break;
            case 5:
                current_call = "polymass_moments_scale";
                for (i = 0; i < 3; ++i) values[i] = take_double(&r);
                status = polymass_moments_scale(target, context, target, values);
                break;
            case 6: {
                const polymass_mass_desc mass = take_mass(&r);
                current_call = "polymass_moments_weight";
                status = polymass_moments_weight(target, context, target, &mass);
                break;
            }
            default: {
                polymass_mass_properties properties, untouched;
                polymass_mass_desc mass = take_mass(&r);
                double point[3];
                for (i = 0; i < 3; ++i) point[i] = take_double(&r);
                current_call = "polymass_moments_mass_properties";
                memset(&properties, 0xA5, sizeof properties);
                properties.struct_size = sizeof properties;
                untouched = properties;
                status = polymass_moments_mass_properties(&properties, context, target,
                                                          (code & 0x80) ? NULL : &mass);
                check_call(status, &properties, &untouched, sizeof properties, context);
                check_properties(status, &properties, context);
                if (status == POLYMASS_OK) {
                    const char* violation = inertia_about_violation(&properties, point);
                    if (violation) fail(__LINE__, violation, status, context);
                }
                continue;
            }
        }
        check_call(status, target, &before, sizeof before, context);
        check_moments(status, target, context);
    }
    polymass_context_destroy(context);
    return 0;
}
