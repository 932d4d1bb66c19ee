#include "library/categories.hpp"

#include <polymass/polymass.h>

namespace polymass_cli {

const char* category_of(int32_t status) {
    switch (status) {
        case POLYMASS_OK:
            return "ok";
        case POLYMASS_ERROR_OPEN:
            return "open";
        case POLYMASS_ERROR_NON_MANIFOLD:
            return "non_manifold";
        case POLYMASS_ERROR_INCONSISTENT_ORIENTATION:
            return "inconsistent_orientation";
        case POLYMASS_ERROR_INTERSECTING:
            return "intersecting";
        case POLYMASS_ERROR_INVERTED:
            return "inverted";
        case POLYMASS_ERROR_NON_FINITE:
            return "non_finite";
        case POLYMASS_ERROR_INDEX_OUT_OF_RANGE:
            return "index_out_of_range";
        case POLYMASS_ERROR_FACE_TOO_SMALL:
            return "face_too_small";
        case POLYMASS_ERROR_NON_PLANAR_FACE:
            return "non_planar_face";
        case POLYMASS_ERROR_ZERO_VOLUME:
            return "zero_volume";
        case POLYMASS_ERROR_OVERFLOW:
            return "overflow";
        case POLYMASS_ERROR_OUT_OF_MEMORY:
            return "out_of_memory";
        case POLYMASS_ERROR_INVALID_ARGUMENT:
            return "invalid_argument";
        default:
            return "internal";
    }
}

ExitCode exit_code_of(int32_t status) {
    switch (status) {
        case POLYMASS_OK:
            return kExitOk;
        case POLYMASS_ERROR_OUT_OF_MEMORY:
        case POLYMASS_ERROR_INVALID_ARGUMENT:
        case POLYMASS_ERROR_INTERNAL:
            return kExitInternal;
        default:
            // Everything else is about the mesh: its topology, its numbers, or
            // a size its results cannot be expressed at.
            return kExitInvalidMesh;
    }
}

}  // namespace polymass_cli
