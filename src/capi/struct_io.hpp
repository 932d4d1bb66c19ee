// Size-prefixed structs: every public struct starts with struct_size, set by
// the caller to sizeof(the struct) it was compiled with. This is version 1 of
// every struct, so exactly that size is accepted; a later version will also
// accept the sizes of the versions before it (fields are only ever appended).
#pragma once

#include <algorithm>
#include <cmath>
#include <iterator>

#include "context.hpp"

namespace polymass::capi {

template <class Struct>
int32_t check_struct(polymass_context* context, const Struct* value, const char* name) {
    if (!value) return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT, "%s is NULL", name);
    if (value->struct_size != sizeof(Struct))
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "%s->struct_size is %u; this library (version %s) expects %u", name,
                             unsigned(value->struct_size), POLYMASS_VERSION_STRING,
                             unsigned(sizeof(Struct)));
    return POLYMASS_OK;
}

// Output structs are only written when every value in them is a number.
template <class Values>
bool all_finite(const Values& values) {
    return std::all_of(std::begin(values), std::end(values),
                       [](double value) { return std::isfinite(value); });
}

}  // namespace polymass::capi
