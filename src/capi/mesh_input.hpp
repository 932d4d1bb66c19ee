// A polymass_mesh_desc checked and turned into the typed core::MeshView it
// describes. Checks here are about the arguments themselves (pointers, sizes,
// types, arithmetic that could overflow) and the face sizes; what the indices
// and coordinates say is core/'s job.
#pragma once

#include <cstddef>
#include <cstdint>

#include "context.hpp"
#include "core/mesh_view.hpp"

namespace polymass::capi {

struct MeshInput {
    uint32_t position_type = POLYMASS_POSITION_FLOAT64;
    uint32_t index_type = POLYMASS_INDEX_UINT32;
    const unsigned char* positions = nullptr;
    std::size_t vertex_count = 0;
    std::size_t position_stride = 0;
    const unsigned char* indices = nullptr;
    std::size_t index_count = 0;
    const uint32_t* face_sizes = nullptr;
    std::size_t face_count = 0;
};

// Fills `input` and returns POLYMASS_OK or POLYMASS_ERROR_INVALID_ARGUMENT,
// with the message. The face sizes must add up to index_count; what a face's
// size says of the surface is core/'s to judge.
int32_t read_mesh_desc(polymass_context* context, const polymass_mesh_desc* desc, MeshInput& input);

// The positions part of read_mesh_desc: fills input's positions, or returns
// POLYMASS_ERROR_INVALID_ARGUMENT with the message.
int32_t read_positions(polymass_context* context, const void* positions, uint32_t position_type,
                       uint64_t vertex_count, uint64_t position_stride, MeshInput& input);

// Narrows an input read by read_mesh_desc to its faces [first_face,
// first_face + face_count), or returns POLYMASS_ERROR_INVALID_ARGUMENT with
// the message when they are not all there.
int32_t select_faces(polymass_context* context, MeshInput& input, uint64_t first_face,
                     uint64_t face_count);

// Calls visit(view) with the core::MeshView<Scalar, Index> matching the input's types.
template <class Visit>
decltype(auto) visit_mesh(const MeshInput& input, Visit&& visit) {
    auto with_positions = [&](auto scalar) -> decltype(auto) {
        using Scalar = decltype(scalar);
        auto view = [&](auto index) {
            using Index = decltype(index);
            return core::MeshView<Scalar, Index>{{input.positions, input.position_stride},
                                                 input.vertex_count,
                                                 {input.indices},
                                                 input.index_count,
                                                 input.face_sizes,
                                                 input.face_count};
        };
        return input.index_type == POLYMASS_INDEX_UINT16 ? visit(view(std::uint16_t{}))
                                                         : visit(view(std::uint32_t{}));
    };
    return input.position_type == POLYMASS_POSITION_FLOAT32 ? with_positions(float{})
                                                            : with_positions(double{});
}

}  // namespace polymass::capi
