#include "model/model.hpp"

namespace polymass_cli {

Part combined_part(const Model& model) {
    if (model.parts.size() == 1) return model.parts.front();
    Part all;
    all.name = "combined";
    for (const Part& part : model.parts) {
        all.indices.insert(all.indices.end(), part.indices.begin(), part.indices.end());
        all.face_sizes.insert(all.face_sizes.end(), part.face_sizes.begin(), part.face_sizes.end());
    }
    return all;
}

uint64_t used_vertices(const Model& model, const Part& part) {
    std::vector<bool> used(model.vertex_count(), false);
    uint64_t count = 0;
    for (const uint32_t index : part.indices) {
        if (index < used.size() && !used[index]) {
            used[index] = true;
            ++count;
        }
    }
    return count;
}

void scale_model(Model& model, double factor) {
    if (factor == 1.0) return;
    for (double& coordinate : model.positions) coordinate *= factor;
}

void triangulate_model(Model& model) {
    for (Part& part : model.parts) {
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
        part = std::move(fanned);
    }
}

}  // namespace polymass_cli
