// polymass_status_string: static names of the status codes.
#include <polymass/polymass.h>

extern "C" POLYMASS_API const char* polymass_status_string(int32_t status) {
    switch (status) {
        case POLYMASS_OK:
            return "success";
        case POLYMASS_ERROR_INVALID_ARGUMENT:
            return "invalid argument";
        case POLYMASS_ERROR_OUT_OF_MEMORY:
            return "out of memory";
        case POLYMASS_ERROR_INTERNAL:
            return "internal error";
        case POLYMASS_ERROR_NON_FINITE:
            return "non-finite coordinate";
        case POLYMASS_ERROR_INDEX_OUT_OF_RANGE:
            return "vertex index out of range";
        case POLYMASS_ERROR_FACE_TOO_SMALL:
            return "face with fewer than 3 vertices";
        case POLYMASS_ERROR_OPEN:
            return "open surface";
        case POLYMASS_ERROR_NON_MANIFOLD:
            return "non-manifold edge";
        case POLYMASS_ERROR_INCONSISTENT_ORIENTATION:
            return "inconsistent face orientation";
        case POLYMASS_ERROR_NON_PLANAR_FACE:
            return "non-planar face";
        case POLYMASS_ERROR_INTERSECTING:
            return "intersecting surface";
        case POLYMASS_ERROR_INVERTED:
            return "inverted solid";
        case POLYMASS_ERROR_ZERO_VOLUME:
            return "zero volume";
        case POLYMASS_ERROR_ZERO_AREA:
            return "zero area";
        case POLYMASS_ERROR_OVERFLOW:
            return "result out of double range";
        default:
            return "unknown status";
    }
}
