#include "surface_overlaps.hpp"

#include "indexed_surface.hpp"
#include "surface_contacts.hpp"

namespace polymass::core {

template <class Scalar, class Index>
SurfaceOverlaps find_overlaps(const MeshView<Scalar, Index>& mesh, const std::uint32_t* vertex_ids,
                              const Eigen::Vector3d& reference, double size, const Shells* shells,
                              bool may_have_copies, TaskRunner& tasks,
                              std::pmr::memory_resource* memory) {
    const IndexedSurface<Scalar, Index> surface(mesh, vertex_ids, reference, size, shells, tasks,
                                                memory, may_have_copies);
    const SurfaceContacts contacts = find_contacts(surface, tasks, memory);
    SurfaceOverlaps result(memory);
    result.crossing = contacts.crossing;
    result.touching = contacts.touching;
    // Crossing faces already bound some region twice: nesting says no more.
    if (shells && shells->count >= 2 && result.crossing.count == 0)
        result.winding_of_shell = count_windings(surface, contacts, tasks, memory);
    return result;
}

#define POLYMASS_INSTANTIATE(Scalar, Index)                                                   \
    template SurfaceOverlaps find_overlaps<Scalar, Index>(                                    \
        const MeshView<Scalar, Index>&, const std::uint32_t*, const Eigen::Vector3d&, double, \
        const Shells*, bool, TaskRunner&, std::pmr::memory_resource*);
POLYMASS_FOR_EACH_MESH_VIEW(POLYMASS_INSTANTIATE)
#undef POLYMASS_INSTANTIATE

}  // namespace polymass::core
