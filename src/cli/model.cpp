#include "model.hpp"

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

void scale_model(Model& model, double factor) {
    if (factor == 1.0) return;
    for (double& coordinate : model.positions) coordinate *= factor;
}

}  // namespace polymass_cli
