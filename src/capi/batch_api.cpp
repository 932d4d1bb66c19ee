// polymass_batch_compute: many meshes in one call, each item with its own
// status and message. The items are independent, so the context's workers
// take them in any order without changing a result.
#include <polymass/polymass.h>

#include <algorithm>
#include <atomic>
#include <cstring>

#include "api_guard.hpp"
#include "struct_io.hpp"

using namespace polymass::capi;

namespace {

// The item's result is the single call's, so it is bit for bit the same; the
// context's message is copied into the item before the next item replaces it.
void compute_item(polymass_batch_item& item, polymass_context* context) {
    const int32_t status = polymass_mass_properties_compute(
        item.properties, item.provenance, context, item.desc, item.options, item.mass);
    item.status = status;
    std::strncpy(item.message, polymass_context_message(context), sizeof item.message - 1);
    item.message[sizeof item.message - 1] = '\0';
}

}  // namespace

extern "C" {

POLYMASS_API int32_t polymass_batch_compute(polymass_batch_item* items, uint64_t item_count,
                                            uint64_t* out_failed, polymass_context* context) {
    return guarded(context, [&] {
        if (out_failed) *out_failed = 0;
        if (item_count == 0) return int32_t(POLYMASS_OK);
        if (const int32_t status = check_struct(context, items, "items")) return status;
        const uint32_t stride = items->struct_size;
        auto* bytes = reinterpret_cast<unsigned char*>(items);
        for (uint64_t i = 0; i < item_count; ++i)
            if (reinterpret_cast<polymass_batch_item*>(bytes + i * stride)->struct_size != stride)
                return context->fail(
                    POLYMASS_ERROR_INVALID_ARGUMENT,
                    "items[%llu].struct_size is %u but items[0]'s is %u: every "
                    "item of a batch has the same",
                    static_cast<unsigned long long>(i),
                    unsigned(
                        reinterpret_cast<polymass_batch_item*>(bytes + i * stride)->struct_size),
                    unsigned(stride));
        // Read and written in place: every field is in the struct's first
        // version (fields a later version appends need read_struct).
        auto item = [&](uint64_t i) -> polymass_batch_item& {
            return *reinterpret_cast<polymass_batch_item*>(bytes + i * stride);
        };
        const std::size_t threads = std::min<uint64_t>(context->threads(), item_count);
        if (threads == 1) {
            for (uint64_t i = 0; i < item_count; ++i) compute_item(item(i), context);
        } else {
            // Each thread takes the next item not yet taken and computes it
            // through its own context: the results do not depend on which.
            for (std::size_t thread = 0; thread < threads; ++thread) context->batch_context(thread);
            std::atomic<uint64_t> next{0};
            context->tasks().run(threads, [&](std::size_t thread) {
                polymass_context* own = context->batch_context(thread);
                for (uint64_t i = next++; i < item_count; i = next++) compute_item(item(i), own);
            });
        }
        uint64_t failed = 0;
        for (uint64_t i = 0; i < item_count; ++i) failed += item(i).status != POLYMASS_OK;
        context->clear_message();
        if (out_failed) *out_failed = failed;
        return int32_t(POLYMASS_OK);
    });
}

}  // extern "C"
