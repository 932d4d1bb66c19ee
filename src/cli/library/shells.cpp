#include "library/shells.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace polymass_cli {
namespace {

struct Box {
    double lo[3] = {INFINITY, INFINITY, INFINITY};
    double hi[3] = {-INFINITY, -INFINITY, -INFINITY};

    bool inside(const Box& outer) const {
        for (int k = 0; k < 3; ++k) {
            if (lo[k] < outer.lo[k] || hi[k] > outer.hi[k]) return false;
        }
        return true;
    }
};

// A shell on its own: the vertices it uses and its faces renumbered, so that
// checking each of many shells does not scan the whole file each time.
Model shell_model(const Model& model, const Part& part, Box& box) {
    Model shell;
    shell.parts.push_back(Part{part.name, {}, part.face_sizes});
    std::unordered_map<uint32_t, uint32_t> renumbered;
    for (const uint32_t index : part.indices) {
        const auto [at, added] =
            renumbered.emplace(index, static_cast<uint32_t>(shell.vertex_count()));
        if (added) {
            const double* p = &model.positions[3 * size_t(index)];
            shell.positions.insert(shell.positions.end(), p, p + 3);
            for (int k = 0; k < 3; ++k) {
                box.lo[k] = std::min(box.lo[k], p[k]);
                box.hi[k] = std::max(box.hi[k], p[k]);
            }
        }
        shell.parts.back().indices.push_back(at->second);
    }
    return shell;
}

}  // namespace

std::vector<Shell> classify_shells(const Library& library, const Model& model, const Part& part,
                                   double whole_signed_volume) {
    // Welding only joins shells: a surface in one piece as given is one piece
    // welded too, and finding that costs no weld (a second one, after the
    // computation's: 0.1 s for a million welded triangles).
    uint64_t count = 0;
    std::vector<uint32_t> shell_of_face = shell_of_each_face(library, model, part, false, count);
    if (count > 1) shell_of_face = shell_of_each_face(library, model, part, true, count);
    if (shell_of_face.empty()) return {};
    const double outward = whole_signed_volume < 0 ? -1.0 : 1.0;
    if (count == 1) {  // the whole surface: nothing to compare it with
        const double volume = outward * whole_signed_volume;
        return {{part.face_sizes.size(), volume, volume > 0 ? "solid" : "no volume"}};
    }
    std::vector<Part> parts(count);
    size_t corner = 0;
    for (size_t face = 0; face < part.face_sizes.size(); ++face) {
        Part& shell = parts[shell_of_face[face]];
        const uint32_t size = part.face_sizes[face];
        shell.indices.insert(shell.indices.end(), part.indices.begin() + corner,
                             part.indices.begin() + corner + size);
        shell.face_sizes.push_back(size);
        corner += size;
    }
    // Outward is what the whole surface says it is (an inverted file taken as
    // such turns every shell).
    std::vector<Shell> shells;
    std::vector<Box> boxes(parts.size());
    for (size_t i = 0; i < parts.size(); ++i) {
        const Model alone = shell_model(model, parts[i], boxes[i]);
        const double volume =
            check_solid(library, alone, alone.parts.front()).diagnostics.signed_volume;
        shells.push_back({parts[i].face_sizes.size(), outward * volume, ""});
    }
    for (size_t i = 0; i < shells.size(); ++i) {
        Shell& shell = shells[i];
        if (!(shell.signed_volume != 0)) {  // zero or NaN (not closed on its own)
            shell.kind = "no volume";
        } else if (shell.signed_volume > 0) {
            shell.kind = "solid";
        } else {
            shell.kind = "inverted";
            for (size_t j = 0; j < shells.size() && shell.kind[0] == 'i'; ++j) {
                if (shells[j].signed_volume > 0 && boxes[i].inside(boxes[j])) shell.kind = "cavity";
            }
        }
    }
    return shells;
}

std::string inverted_shell_message(const std::vector<Shell>& shells) {
    for (size_t i = 0; i < shells.size(); ++i) {
        if (std::string(shells[i].kind) == "inverted") {
            return "shell " + std::to_string(i + 1) + " (" + std::to_string(shells[i].faces) +
                   " faces) is inside out: its volume is negative and it lies outside every "
                   "solid shell";
        }
    }
    return "";
}

}  // namespace polymass_cli
