#include "model/model.hpp"

#include <algorithm>

namespace polymass_cli {

void Part::drop_triangle_sizes() {
    if (std::all_of(face_sizes.begin(), face_sizes.end(), [](uint32_t size) { return size == 3; }))
        std::vector<uint32_t>().swap(face_sizes);
}

std::vector<double>& Positions::as_doubles() {
    if (is_float32()) {
        wide_.assign(narrow_.begin(), narrow_.end());
        std::vector<float>().swap(narrow_);
    }
    return wide_;
}

Part combined_part(const Model& model) {
    if (model.parts.size() == 1) return model.parts.front();
    Part all;
    all.name = "combined";
    const bool triangles = std::all_of(model.parts.begin(), model.parts.end(),
                                       [](const Part& part) { return part.face_sizes.empty(); });
    for (const Part& part : model.parts) {
        all.indices.insert(all.indices.end(), part.indices.begin(), part.indices.end());
        if (triangles) continue;
        for (uint64_t face = 0; face < part.face_count(); ++face)
            all.face_sizes.push_back(part.face_size(face));
    }
    return all;
}

uint64_t used_vertices(const Model& model, const Part& part) {
    // A byte a vertex, not a bit, written whatever it held: half the
    // instructions on every corner of the file.
    std::vector<uint8_t> used(model.vertex_count(), 0);
    for (const uint32_t index : part.indices)
        if (index < used.size()) used[index] = 1;
    return uint64_t(std::count(used.begin(), used.end(), uint8_t(1)));
}

void scale_model(Model& model, double factor) {
    if (factor == 1.0) return;
    for (double& coordinate : model.positions.as_doubles()) coordinate *= factor;
}

void triangulate_model(Model& model) {
    for (Part& part : model.parts) {
        if (part.face_sizes.empty()) continue;  // triangles only
        Part fanned{part.name, {}, {}};
        size_t corner = 0;
        for (const uint32_t size : part.face_sizes) {
            const uint32_t* face = part.indices.data() + corner;
            corner += size;
            if (size <= 3) {  // triangles, and faces too small for the library to name
                fanned.indices.insert(fanned.indices.end(), face, face + size);
                fanned.face_sizes.push_back(size);
                continue;
            }
            for (uint32_t k = 1; k + 1 < size; ++k) {
                fanned.indices.insert(fanned.indices.end(), {face[0], face[k], face[k + 1]});
                fanned.face_sizes.push_back(3);
            }
        }
        fanned.drop_triangle_sizes();
        part = std::move(fanned);
    }
}

}  // namespace polymass_cli
