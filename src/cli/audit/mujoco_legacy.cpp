#include "audit/mujoco_legacy.hpp"

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <vector>

namespace polymass_cli::audit {
namespace {

// MuJoCo's smallest area and volume of a mesh it accepts.
constexpr double kSmallest = 1e-15;

using Triangle = std::array<Eigen::Vector3d, 3>;

std::vector<Triangle> triangles_of(const Model& model, const Eigen::Vector3d& scale) {
    const auto vertex = [&](uint32_t index) -> Eigen::Vector3d {
        const std::array<double, 3> p = model.positions.vertex(index);
        return Eigen::Vector3d(p[0], p[1], p[2]).cwiseProduct(scale);
    };
    std::vector<Triangle> triangles;
    for (const Part& part : model.parts) {
        std::size_t first = 0;
        for (uint64_t face = 0; face < part.face_count(); ++face) {
            const uint32_t size = part.face_size(face);
            for (uint32_t k = 1; k + 1 < size; ++k) {
                triangles.push_back({vertex(part.indices[first]), vertex(part.indices[first + k]),
                                     vertex(part.indices[first + k + 1])});
            }
            first += size;
        }
    }
    return triangles;
}

// The volume of the pyramid from apex over the triangle, counted positive.
double pyramid(const Triangle& t, const Eigen::Vector3d& apex) {
    return std::abs((t[0] - apex).dot((t[1] - apex).cross(t[2] - apex))) / 6;
}

}  // namespace

std::optional<polymass_moments> mujoco_legacy_moments(const Model& model,
                                                      const Eigen::Vector3d& scale) {
    const std::vector<Triangle> triangles = triangles_of(model, scale);
    // The area centroid of the faces.
    double area = 0.0;
    Eigen::Vector3d faces_centre = Eigen::Vector3d::Zero();
    for (const Triangle& t : triangles) {
        const double a = (t[1] - t[0]).cross(t[2] - t[0]).norm() / 2;
        area += a;
        faces_centre += a * (t[0] + t[1] + t[2]) / 3;
    }
    if (!(area >= kSmallest)) return std::nullopt;
    faces_centre /= area;
    // The centre of mass of the pyramids from it (each pyramid's at 3/4 of
    // the way from its apex to its base's centroid).
    double volume = 0.0;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (const Triangle& t : triangles) {
        const double v = pyramid(t, faces_centre);
        volume += v;
        centre += v * ((t[0] + t[1] + t[2]) / 4 + faces_centre / 4);
    }
    if (!(volume >= kSmallest)) return std::nullopt;
    centre /= volume;
    // The tetrahedra from the centre of mass: for one of volume V over
    // d, e, f (from its apex), int x_i x_j = V/20 (2 (d_i d_j + e_i e_j +
    // f_i f_j) + d_i e_j + d_j e_i + d_i f_j + d_j f_i + e_i f_j + e_j f_i).
    polymass_moments moments{};
    polymass_moments_init(&moments, sizeof moments);
    static const int kPairs[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}};
    for (const Triangle& t : triangles) {
        const Eigen::Vector3d d = t[0] - centre, e = t[1] - centre, f = t[2] - centre;
        const double v = pyramid(t, centre);
        moments.volume += v;
        for (int k = 0; k < 6; ++k) {
            const int i = kPairs[k][0], j = kPairs[k][1];
            moments.second[k] +=
                v / 20 *
                (2 * (d[i] * d[j] + e[i] * e[j] + f[i] * f[j]) + d[i] * e[j] + d[j] * e[i] +
                 d[i] * f[j] + d[j] * f[i] + e[i] * f[j] + e[j] * f[i]);
        }
    }
    if (!(moments.volume >= kSmallest)) return std::nullopt;
    moments.mass = moments.volume;
    for (int k = 0; k < 3; ++k) moments.reference[k] = centre[k];
    return moments;
}

}  // namespace polymass_cli::audit
