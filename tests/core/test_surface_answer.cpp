// The chain of modes as the core decides it (answer_surface,
// surface_answer.cpp), below the C API's translation: which mode answers,
// the failures in the order tried (the solid's verdict once, however often
// the chain names solid or repair), the refusals of each mode, the checks a
// caller skips by name, and the bodies' numbers against closed forms. Each
// case also far from the origin.
#include "core/surface_answer.hpp"

#include "check.hpp"
#include "test_mesh.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <memory_resource>

#include "core/rigid_body.hpp"

namespace {

using polymass::core::AnswerSettings;
using polymass::core::Defect;
using polymass::core::Mode;
using polymass::core::Refusal;
using polymass::core::SurfaceAnswer;
using polymass_test::TestMesh;

// The unit cube at `corner`, twelve outward triangles.
TestMesh unit_cube(const Eigen::Vector3d& corner) {
    return polymass_test::box_mesh(corner, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(),
                                   Eigen::Vector3d::UnitZ(), true);
}

// Two unit cubes, the second moved by (1/2, 1/2, 1/2): they overlap in an
// eighth of a cube, so the solid they bound is 1.875 and the sum of their
// volumes 2.
TestMesh overlapping_cubes(const Eigen::Vector3d& corner) {
    TestMesh mesh = unit_cube(corner);
    polymass_test::append(mesh, unit_cube(corner + Eigen::Vector3d::Constant(0.5)));
    return mesh;
}

SurfaceAnswer answer(const TestMesh& mesh, std::initializer_list<Mode> modes,
                     AnswerSettings settings = {}) {
    for (const Mode mode : modes) settings.modes[settings.mode_count++] = mode;
    return polymass::core::answer_surface(mesh.view(), settings, std::pmr::get_default_resource());
}

double volume_of(const SurfaceAnswer& answer) {
    return polymass::core::rigid_body(answer.body.integrals, answer.body.reference, 1.0).volume;
}

bool close(double value, double expected, double tolerance) {
    return std::abs(value - expected) <= tolerance * std::max(1.0, std::abs(expected));
}

bool failed_as(const SurfaceAnswer& answer, std::size_t i, Mode mode, Refusal refusal,
               Defect defect = Defect::none) {
    if (i >= answer.failure_count) return false;
    const polymass::core::ModeFailure& failure = answer.failures[i];
    return failure.mode == mode && failure.refusal == refusal && failure.defect == defect;
}

void test_a_valid_solid_answers_in_solid_and_repair(const Eigen::Vector3d& at) {
    for (const std::initializer_list<Mode> chain : {std::initializer_list<Mode>{},
                                                    {Mode::solid},
                                                    {Mode::repair},
                                                    {Mode::hull, Mode::solid}}) {
        const SurfaceAnswer cube = answer(unit_cube(at), chain);
        const bool hull_first = chain.size() == 2;
        CHECK(cube.answered == (hull_first ? Mode::hull : Mode::solid));
        CHECK(cube.failure_count == 0);
        CHECK(close(volume_of(cube), 1.0, 1e-14));
        // Every check ran: nothing unchecked is flagged.
        CHECK((cube.body.warnings & polymass::core::kWarningIntersectionsUnchecked) == 0);
    }
}

// The defaults run the intersection check: crossing parts are refused. A
// caller who skips it by name gets the sum of the parts, flagged.
void test_crossing_parts_are_refused_unless_the_check_is_skipped(const Eigen::Vector3d& at) {
    const TestMesh mesh = overlapping_cubes(at);
    const SurfaceAnswer checked = answer(mesh, {});
    CHECK(!checked.answered);
    CHECK(checked.failure_count == 1);
    CHECK(failed_as(checked, 0, Mode::solid, Refusal::defect, Defect::crossing));

    AnswerSettings trusted;
    trusted.analysis.check_intersections = false;
    const SurfaceAnswer unchecked = answer(mesh, {}, trusted);
    CHECK(unchecked.answered == Mode::solid);
    CHECK(close(volume_of(unchecked), 2.0, 1e-14));
    CHECK((unchecked.body.warnings & polymass::core::kWarningIntersectionsUnchecked) != 0);
}

// The solid's verdict is a failure once, however often the chain asks for
// it; the hull then answers with its bound: the hull of a cube and its copy
// moved by t is the cube swept along t, of volume 1 + sqrt(3) |t| (the
// cube's shadow along (1, 1, 1) is a hexagon of area sqrt(3)) = 2.5.
void test_the_hull_answers_after_the_solid_once(const Eigen::Vector3d& at) {
    const SurfaceAnswer hull =
        answer(overlapping_cubes(at), {Mode::solid, Mode::solid, Mode::hull});
    CHECK(hull.answered == Mode::hull);
    CHECK(hull.failure_count == 1);
    CHECK(failed_as(hull, 0, Mode::solid, Refusal::defect, Defect::crossing));
    CHECK(close(volume_of(hull), 2.5, 1e-14));
    CHECK(close(hull.hull_volume, 2.5, 1e-14));
    CHECK(hull.hull_vertex_count == 14);  // 16 corners, two of them inside
    CHECK((hull.body.warnings & polymass::core::kWarningHull) != 0);
    // The true solid lies inside the hull: its volume is off by at most the
    // hull's, its centre of mass by the box's largest side (1.5).
    CHECK(close(hull.body.approximation.volume, 2.5, 1e-14));
    CHECK(close(hull.body.approximation.center_of_mass, 1.5, 1e-14));
}

// A cube missing one triangle is open; repair caps the hole and answers the
// whole cube; the solid's failure says why it was needed.
void test_repair_closes_an_open_cube(const Eigen::Vector3d& at) {
    TestMesh open = unit_cube(at);
    open.indices.resize(open.indices.size() - 3);
    open.face_sizes.pop_back();
    const SurfaceAnswer repaired = answer(open, {Mode::solid, Mode::repair});
    CHECK(repaired.answered == Mode::repair);
    CHECK(failed_as(repaired, 0, Mode::solid, Refusal::defect, Defect::open));
    CHECK(close(volume_of(repaired), 1.0, 1e-14));
    CHECK((repaired.body.warnings & polymass::core::kWarningRepaired) != 0);
    // Solid alone: refused, nothing answered.
    const SurfaceAnswer refused = answer(open, {Mode::solid});
    CHECK(!refused.answered && failed_as(refused, 0, Mode::solid, Refusal::defect, Defect::open));
}

// A surface of triangles not welded is integrated with its scan
// (analyse_mesh), before its topology is checked; the integrals are the
// analysis's only once the topology lets it go on: an open cube's analysis
// stopped at its first problem has none, as when the integration came after
// the topology, and one asked for every finding has them.
void test_integrals_kept_only_past_the_topology(const Eigen::Vector3d& at) {
    TestMesh open = unit_cube(at);
    open.indices.resize(open.indices.size() - 3);
    open.face_sizes.pop_back();
    polymass::core::AnalysisSettings settings;
    settings.check_intersections = false;
    const polymass::core::MeshAnalysis stopped =
        polymass::core::analyse_mesh(open.view(), settings, std::pmr::get_default_resource());
    CHECK(stopped.topology && stopped.verdict.defect == Defect::open);
    CHECK(!stopped.integration);
    settings.stop_at_first_problem = false;
    const polymass::core::MeshAnalysis full =
        polymass::core::analyse_mesh(open.view(), settings, std::pmr::get_default_resource());
    CHECK(full.verdict.defect == Defect::open && full.integration);
}

// Modes that cannot make a body of a flat square (two triangles and their
// reverses: a sheet of no volume) refuse it each for its own reason, in the
// order tried: the hull of coplanar points; and the shell mode of a surface
// with no area (triangles on a line).
void test_each_mode_refuses_for_its_own_reason(const Eigen::Vector3d& at) {
    TestMesh sheet;
    for (const Eigen::Vector3d& corner : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0),
                                          Eigen::Vector3d(1, 1, 0), Eigen::Vector3d(0, 1, 0)})
        sheet.add_vertex(at + corner);
    sheet.add_face({0, 1, 2});
    sheet.add_face({0, 2, 3});
    sheet.add_face({0, 2, 1});
    sheet.add_face({0, 3, 2});
    const SurfaceAnswer flat = answer(sheet, {Mode::solid, Mode::hull});
    CHECK(!flat.answered);
    CHECK(flat.failure_count == 2);
    CHECK(flat.failure_count == 2 && flat.failures[0].mode == Mode::solid &&
          flat.failures[0].defect != Defect::none);
    CHECK(failed_as(flat, 1, Mode::hull, Refusal::hull_coplanar));

    TestMesh line;
    for (int k = 0; k < 4; ++k) line.add_vertex(at + Eigen::Vector3d(k, 0, 0));
    line.add_face({0, 1, 2});
    line.add_face({1, 3, 2});
    AnswerSettings shell;
    shell.shell_thickness = 0.01;
    const SurfaceAnswer no_area = answer(line, {Mode::shell, Mode::hull}, shell);
    CHECK(!no_area.answered);
    CHECK(failed_as(no_area, 0, Mode::shell, Refusal::no_area));
    CHECK(failed_as(no_area, 1, Mode::hull, Refusal::hull_collinear));
}

// A NaN coordinate gives no body in any mode: each says non_finite.
void test_a_nan_is_non_finite_in_every_mode(const Eigen::Vector3d& at) {
    TestMesh cube = unit_cube(at);
    cube.coordinates[4] = std::numeric_limits<double>::quiet_NaN();
    AnswerSettings shell;
    shell.shell_thickness = 0.01;
    const SurfaceAnswer nan =
        answer(cube, {Mode::solid, Mode::repair, Mode::shell, Mode::hull}, shell);
    CHECK(!nan.answered);
    CHECK(nan.failure_count == 4);
    const Mode modes[] = {Mode::solid, Mode::repair, Mode::shell, Mode::hull};
    for (std::size_t i = 0; i < 4; ++i)
        CHECK(failed_as(nan, i, modes[i], Refusal::defect, Defect::non_finite));
}

// The findings in full (stop_at_first_problem false) and the one-call form
// give the same answer.
void test_findings_in_full_answer_as_the_first_problem_does(const Eigen::Vector3d& at) {
    AnswerSettings full;
    full.analysis.stop_at_first_problem = false;
    for (const TestMesh& mesh : {unit_cube(at), overlapping_cubes(at)}) {
        const SurfaceAnswer first = answer(mesh, {Mode::solid, Mode::hull});
        const SurfaceAnswer all = answer(mesh, {Mode::solid, Mode::hull}, full);
        CHECK(first.answered == all.answered);
        CHECK(first.failure_count == all.failure_count);
        CHECK(volume_of(first) == volume_of(all));
    }
}

}  // namespace

int main() {
    for (const Eigen::Vector3d& at : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1e6, -2e6, 3e6),
                                      Eigen::Vector3d(-1e8, 1e8, 5e7)}) {
        test_a_valid_solid_answers_in_solid_and_repair(at);
        test_crossing_parts_are_refused_unless_the_check_is_skipped(at);
        test_the_hull_answers_after_the_solid_once(at);
        test_repair_closes_an_open_cube(at);
        test_integrals_kept_only_past_the_topology(at);
        test_each_mode_refuses_for_its_own_reason(at);
        test_a_nan_is_non_finite_in_every_mode(at);
        test_findings_in_full_answer_as_the_first_problem_does(at);
    }
    return polymass_test::finish("test_surface_answer");
}
