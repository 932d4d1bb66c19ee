// A game engine's load path: a triangle mesh in, a Bullet rigid body out.
//
// The mesh is what an engine keeps for rendering: an interleaved float32
// vertex buffer (position, normal) and 16-bit triangle indices. libpolymass
// reads the positions in place through their byte stride, checks that they
// bound a solid and computes its mass properties in one call. Bullet wants a
// body whose origin is the centre of mass and whose axes are the principal
// axes, with the principal moments as its local inertia: the body is placed
// at the principal frame, and its collision shape is the same triangles
// moved into that frame.
//
// The part is a steel T-bar, turned and moved away from the origin so that
// none of its principal axes is a coordinate axis. Its three principal
// moments differ, so a spin about the intermediate axis is unstable (the
// tennis-racket theorem): with gravity off, the body flips over and back while
// its angular momentum in the world frame stays what it was. The example
// checks both, so it is also a test (ctest example.bullet.rigid_body): it
// returns 1 if Bullet's principal moments, or the inertia tensor it derives
// from them and the body's frame, are not polymass's, if no flip happens, or
// if the angular momentum drifts more than kMomentumTolerance.
//
//   c++ -std=c++17 rigid_body_from_mesh.cpp $(pkg-config --cflags --libs polymass bullet)

#include <BulletCollision/Gimpact/btGImpactCollisionAlgorithm.h>
#include <BulletCollision/Gimpact/btGImpactShape.h>
#include <btBulletDynamicsCommon.h>
#include <polymass/polymass.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <vector>

namespace {

// Bullet's implicit gyroscopic step loses angular momentum in proportion to
// the turn per step: measured with Bullet 3.24 over these 6 s, 9.5e-3 of it at
// 10 rad/s and 1 kHz (3.9e-2 at 240 Hz). The tolerance leaves twice that.
constexpr double kMomentumTolerance = 2e-2;
constexpr double kSteelDensity = 7850.0;  // kg/m^3
constexpr double kTimeStep = 1.0 / 1000.0;
constexpr int kSteps = 1000 * 6;  // 6 s: two flips at the spin below
constexpr double kSpin = 10.0;    // rad/s about the intermediate axis

struct Vertex {
    float position[3];
    float normal[3];  // unused here; an engine's buffer carries it
};

struct EngineMesh {
    std::vector<Vertex> vertices;
    std::vector<uint16_t> indices;  // triangles, counter-clockwise from outside
};

// The T-shaped profile in the xy plane (metres), counter-clockwise from +z:
// a crossbar 360 x 60 mm with a stem 60 x 180 mm on it, extruded 60 mm along z.
constexpr std::array<std::array<float, 2>, 8> kProfile = {{
    {-0.18f, 0.00f},
    {0.18f, 0.00f},
    {0.18f, 0.06f},
    {0.03f, 0.06f},
    {0.03f, 0.24f},
    {-0.03f, 0.24f},
    {-0.03f, 0.06f},
    {-0.18f, 0.06f},
}};
// The profile cut into triangles, counter-clockwise from +z.
constexpr std::array<std::array<uint16_t, 3>, 6> kProfileTriangles = {{
    {0, 1, 2},
    {0, 2, 3},
    {0, 3, 6},
    {0, 6, 7},
    {6, 3, 4},
    {6, 4, 5},
}};
constexpr float kDepth = 0.06f;

// The T-bar as an engine would load it: turned by 40 degrees about
// (1, 2, 3) and moved to (3, -1, 2) metres.
EngineMesh t_handle() {
    const btTransform placement(btQuaternion(btVector3(1, 2, 3).normalized(), btRadians(40)),
                                btVector3(3, -1, 2));
    EngineMesh mesh;
    for (float z : {0.0f, kDepth}) {
        for (const auto& corner : kProfile) {
            const btVector3 p = placement * btVector3(corner[0], corner[1], z);
            mesh.vertices.push_back({{float(p.x()), float(p.y()), float(p.z())}, {0, 0, 0}});
        }
    }
    const uint16_t n = kProfile.size();  // the top cap's vertices are n..2n-1
    for (const auto& t : kProfileTriangles) {
        mesh.indices.insert(mesh.indices.end(), {t[2], t[1], t[0]});  // bottom, seen from -z
        mesh.indices.insert(mesh.indices.end(),
                            {uint16_t(t[0] + n), uint16_t(t[1] + n), uint16_t(t[2] + n)});  // top
    }
    for (uint16_t i = 0; i < n; ++i) {  // a side quad on each profile edge
        const uint16_t j = (i + 1) % n;
        mesh.indices.insert(mesh.indices.end(),
                            {i, j, uint16_t(j + n), i, uint16_t(j + n), uint16_t(i + n)});
    }
    return mesh;
}

// The mass properties of the mesh from its vertex buffer, read in place.
bool mass_properties_of(const EngineMesh& mesh, double density,
                        polymass_mass_properties* properties) {
    polymass_context* context = nullptr;
    if (polymass_context_create(&context, nullptr) != POLYMASS_OK) return false;
    polymass_mesh_desc desc;
    polymass_mesh_desc_init(&desc, sizeof desc);
    desc.position_type = POLYMASS_POSITION_FLOAT32;
    desc.positions = mesh.vertices.data()->position;
    desc.position_stride = sizeof(Vertex);  // interleaved: no copy
    desc.vertex_count = mesh.vertices.size();
    desc.index_type = POLYMASS_INDEX_UINT16;
    desc.indices = mesh.indices.data();
    desc.index_count = mesh.indices.size();
    // face_sizes NULL and face_count 0: every three indices are a triangle.
    polymass_mass_desc mass;
    polymass_mass_desc_init(&mass, sizeof mass);
    mass.mass_mode = POLYMASS_MASS_FROM_DENSITY;
    mass.density = density;
    polymass_mass_properties_init(properties, sizeof *properties);
    // No provenance wanted; no options: every check, the exact solid or an error.
    const int32_t status =
        polymass_mass_properties_compute(properties, nullptr, context, &desc, nullptr, &mass);
    if (status != POLYMASS_OK) {
        std::fprintf(stderr, "polymass: %s (%s)\n", polymass_status_string(status),
                     polymass_context_message(context));
    }
    polymass_context_destroy(context);
    return status == POLYMASS_OK;
}

// The principal frame: origin at the centre of mass, axes the principal axes
// (the columns of polymass's row-major rotation, det +1).
btTransform principal_frame(const polymass_mass_properties& p) {
    const double* r = p.principal_axes;
    const btMatrix3x3 axes(r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7], r[8]);
    return btTransform(axes,
                       btVector3(p.center_of_mass[0], p.center_of_mass[1], p.center_of_mass[2]));
}

// Everything a rigid body needs kept alive beside it.
struct Body {
    std::vector<btVector3> frame_positions;  // the vertices in the principal frame
    std::vector<int> indices;
    std::unique_ptr<btTriangleIndexVertexArray> triangles;
    std::unique_ptr<btGImpactMeshShape> shape;
    std::unique_ptr<btDefaultMotionState> motion_state;
    std::unique_ptr<btRigidBody> body;
};

// Bullet's implicit gyroscopic step (BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY)
// solves a 3 x 3 system in single precision and skips it, silently, when the
// system's determinant is below FLT_EPSILON: for a body whose principal
// moments multiply to less than about 1.2e-7, such as a hand-sized steel part
// in kg m^2, the spin then never precesses. Measured with Bullet 3.24: moments
// of 3e-3, 5e-3 and 7.6e-3 kg m^2 do not turn over, twice those do.
bool bullet_integrates_gyroscopic_term(const polymass_mass_properties& p) {
    return p.principal_moments[0] * p.principal_moments[1] * p.principal_moments[2] >
           std::numeric_limits<float>::epsilon();
}

std::unique_ptr<Body> rigid_body(const EngineMesh& mesh, const polymass_mass_properties& p) {
    auto out = std::make_unique<Body>();
    const btTransform frame = principal_frame(p);
    const btTransform to_frame = frame.inverse();
    for (const Vertex& v : mesh.vertices) {
        out->frame_positions.push_back(to_frame *
                                       btVector3(v.position[0], v.position[1], v.position[2]));
    }
    out->indices.assign(mesh.indices.begin(), mesh.indices.end());
    out->triangles = std::make_unique<btTriangleIndexVertexArray>(
        int(out->indices.size() / 3), out->indices.data(), int(3 * sizeof(int)),
        int(out->frame_positions.size()), out->frame_positions[0].m_floats, int(sizeof(btVector3)));
    out->shape = std::make_unique<btGImpactMeshShape>(out->triangles.get());
    out->shape->updateBound();
    out->motion_state = std::make_unique<btDefaultMotionState>(frame);
    const btVector3 inertia(p.principal_moments[0], p.principal_moments[1], p.principal_moments[2]);
    btRigidBody::btRigidBodyConstructionInfo info(btScalar(p.mass), out->motion_state.get(),
                                                  out->shape.get(), inertia);
    out->body = std::make_unique<btRigidBody>(info);
    return out;
}

btVector3 angular_momentum(const btRigidBody& body) {
    return body.getInvInertiaTensorWorld().inverse() * body.getAngularVelocity();
}

double relative_difference(double a, double b) { return std::abs(a - b) / std::abs(b); }

}  // namespace

int main() {
    const EngineMesh mesh = t_handle();
    polymass_mass_properties p;
    if (!mass_properties_of(mesh, kSteelDensity, &p)) return 1;
    std::printf("mass               %.6g kg\n", p.mass);
    std::printf("centre of mass     (%.6g, %.6g, %.6g) m\n", p.center_of_mass[0],
                p.center_of_mass[1], p.center_of_mass[2]);
    std::printf("principal moments  %.6e %.6e %.6e kg m^2\n", p.principal_moments[0],
                p.principal_moments[1], p.principal_moments[2]);

    btDefaultCollisionConfiguration configuration;
    btCollisionDispatcher dispatcher(&configuration);
    btGImpactCollisionAlgorithm::registerAlgorithm(&dispatcher);
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &configuration);
    world.setGravity(btVector3(0, 0, 0));

    std::unique_ptr<Body> handle = rigid_body(mesh, p);
    btRigidBody& body = *handle->body;
    body.setFlags(body.getFlags() | BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY);
    body.setActivationState(DISABLE_DEACTIVATION);
    world.addRigidBody(&body);

    if (!bullet_integrates_gyroscopic_term(p)) {
        std::printf(
            "note: Bullet will skip this body's gyroscopic term (moments too small "
            "in these units)\n");
    }

    // Bullet keeps the inverse of the local inertia, in floats.
    const btVector3 bullet_moments = body.getLocalInertia();
    double moment_error = 0;
    for (int i = 0; i < 3; ++i) {
        moment_error =
            std::max(moment_error, relative_difference(bullet_moments[i], p.principal_moments[i]));
    }
    std::printf("Bullet's moments   %.6e %.6e %.6e kg m^2 (largest difference %.1e)\n",
                bullet_moments[0], bullet_moments[1], bullet_moments[2], moment_error);
    // The tensor Bullet derives in the world frame, R diag(moments) R^T, is
    // polymass's inertia about the centre of mass if the frame is right.
    const btMatrix3x3 bullet_tensor = body.getInvInertiaTensorWorld().inverse();
    double tensor_error = 0;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            tensor_error =
                std::max(tensor_error, std::abs(bullet_tensor[i][j] - p.inertia[3 * i + j]) /
                                           p.principal_moments[2]);
        }
    }
    std::printf("Bullet's tensor    within %.1e of polymass's (of the largest moment)\n",
                tensor_error);

    // A spin about the intermediate axis (body axis 1), nudged off it.
    const btMatrix3x3& axes = body.getWorldTransform().getBasis();
    body.setAngularVelocity(axes * btVector3(1e-3, kSpin, 1e-3));
    const btVector3 initial_momentum = angular_momentum(body);

    double largest_drift = 0;
    int flips = 0;
    bool along_positive = true;
    for (int step = 0; step < kSteps; ++step) {
        world.stepSimulation(btScalar(kTimeStep), 1, btScalar(kTimeStep));
        const btVector3 momentum = angular_momentum(body);
        largest_drift = std::max(largest_drift, double((momentum - initial_momentum).length() /
                                                       initial_momentum.length()));
        // The intermediate axis turns over: its component of the spin changes sign.
        const btVector3 body_spin =
            body.getWorldTransform().getBasis().transpose() * body.getAngularVelocity();
        if ((body_spin.y() > 0) != along_positive) {
            along_positive = !along_positive;
            ++flips;
        }
    }
    std::printf(
        "after %.1f s        %d flips of the intermediate axis; angular momentum "
        "within %.1e of its start\n",
        kSteps * kTimeStep, flips, largest_drift);
    world.removeRigidBody(&body);

    const double float_precision = 4 * std::numeric_limits<btScalar>::epsilon();
    bool ok = true;
    if (moment_error > float_precision) {
        std::fprintf(stderr, "failed: Bullet's principal moments are not polymass's\n");
        ok = false;
    }
    if (tensor_error > 16 * float_precision) {
        std::fprintf(stderr, "failed: Bullet's inertia tensor is not polymass's\n");
        ok = false;
    }
    if (flips < 2) {
        std::fprintf(stderr, "failed: the spin about the intermediate axis did not turn over\n");
        ok = false;
    }
    if (largest_drift > kMomentumTolerance) {
        std::fprintf(stderr, "failed: the angular momentum drifted by %.2e (> %.0e)\n",
                     largest_drift, kMomentumTolerance);
        ok = false;
    }
    return ok ? 0 : 1;
}
