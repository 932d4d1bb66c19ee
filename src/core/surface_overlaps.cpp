#include "surface_overlaps.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <atomic>
#include <memory_resource>
#include <utility>

#include "box_tree.hpp"
#include "exact_predicates.hpp"
#include "face_blocks.hpp"
#include "position_hash.hpp"
#include "radix_sort.hpp"
#include "surface_triangles.hpp"
#include "triangle_contact.hpp"
#include "volume_integrals.hpp"

namespace polymass::core {
namespace {

using FacePair = std::array<std::uint64_t, 2>;

void sort_unique(std::pmr::vector<FacePair>& pairs) {
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
}

// Where a nesting probe starts: a vertex p of a shell, or inside a triangle
// p, a, b of it, at p + e (a - p) + e^2 (b - p) for e -> 0+, a point of the
// open triangle next to p. Every predicate of a probe is affine in its start
// point, so its sign there is the first nonzero of its signs at p, a and b.
struct ProbeStart {
    Eigen::Vector3d p, a, b;
    bool inside;
};

template <class Predicate>
int sign_at(const ProbeStart& start, const Predicate& predicate) {
    int sign = predicate(start.p);
    if (sign != 0 || !start.inside) return sign;
    sign = predicate(start.a);
    return sign != 0 ? sign : predicate(start.b);
}

// Whether the start, on the plane of t, lies on the closed triangle t:
// exact, in the coordinate plane the triangle projects onto best.
bool lies_on(const Triangle& t, const ProbeStart& start) {
    int drop = 0;
    (t[1] - t[0]).cross(t[2] - t[0]).cwiseAbs().maxCoeff(&drop);
    const int u = (drop + 1) % 3, v = (drop + 2) % 3;
    auto flat = [&](const Eigen::Vector3d& x) { return Eigen::Vector2d(x[u], x[v]); };
    const int turn = orient2d(flat(t[0]), flat(t[1]), flat(t[2]));
    for (int k = 0; k < 3; ++k) {
        const int side = sign_at(start, [&](const Eigen::Vector3d& x) {
            return orient2d(flat(t[k]), flat(t[(k + 1) % 3]), flat(x));
        });
        if (side == -turn) return false;
    }
    return true;
}

// Directions of the probing segments: far from every coordinate plane and
// from each other, so that the next one avoids what grazed the last.
const Eigen::Vector3d kProbeDirections[] = {
    {0.4353, 0.5209, 0.7342}, {-0.6016, 0.3187, 0.7326}, {0.2679, -0.8535, 0.4472}};
// Vertices of a shell tried as probes before its nesting is left unknown.
constexpr std::size_t kProbeVertices = 4;

// Face pairs of one kind (crossing, touching) as the candidates come, in any
// order and with repeats (a polygon's triangles): every distinct pair is
// counted until kMostCountedPairs are; past that, the count is that many (a
// lower bound) and only a pair that would be among the lowest kKeptLocations
// is still wanted. Piles of coincident copies of a part meet in millions of
// pairs: counting them all took minutes and told nothing the first thousands
// do not. wants() only grows stricter, and for larger pairs.
//
// The pieces of the search (BoxTree::pair_tasks) collect on their own and
// are merged: the count is the number of distinct pairs, or
// kMostCountedPairs when there are at least that many, and the lowest pairs
// are exact, however the pairs were cut into pieces and in whatever order
// they came.
class PairCollector {
public:
    static constexpr std::size_t kMostCountedPairs = 2048;

    explicit PairCollector(std::pmr::memory_resource* memory) : pairs_(memory) {}

    // Whether a test of pair could change the finding.
    bool wants(const FacePair& pair) const {
        return !stopped_ || kept_ < kKeptLocations || pair < lowest_[kKeptLocations - 1];
    }

    void add(const FacePair& pair) {
        keep_if_lowest(pair);
        if (stopped_) return;
        pairs_.push_back(pair);
        if (pairs_.size() >= next_tidy_) tidy();
    }

    // Takes in what another piece of the search collected.
    void merge(const PairCollector& piece) {
        for (std::size_t i = 0; i < piece.kept_; ++i) keep_if_lowest(piece.lowest_[i]);
        if (stopped_) return;
        pairs_.insert(pairs_.end(), piece.pairs_.begin(), piece.pairs_.end());
        stopped_ = piece.stopped_;
        tidy();
    }

    // The pairs counted, without those `except` holds. Past the stop the
    // count is a lower bound (complete false).
    PairFinding finding(const PairCollector* except = nullptr) {
        sort_unique(pairs_);
        auto excepted = [&](const FacePair& pair) { return except && except->holds(pair); };
        pairs_.erase(std::remove_if(pairs_.begin(), pairs_.end(), excepted), pairs_.end());
        PairFinding found = PairFinding::of(pairs_);
        if (stopped_) {
            // The lowest pairs were kept apart past the stop.
            std::size_t kept = 0;
            for (std::size_t i = 0; i < kept_; ++i)
                if (!excepted(lowest_[i])) found.lowest[kept++] = lowest_[i];
            found.count = std::max(std::min(found.count, kMostCountedPairs), kept);
            found.complete = false;
        }
        return found;
    }

    // Whether pair was counted or kept (after finding(): pairs_ is sorted).
    bool holds(const FacePair& pair) const {
        return std::binary_search(pairs_.begin(), pairs_.end(), pair) ||
               std::binary_search(lowest_.begin(), lowest_.begin() + kept_, pair);
    }

private:
    // Drops repeats and stops at kMostCountedPairs distinct pairs; the next
    // tidy comes after as many more pairs, so that each costs a sort of at
    // most twice that many.
    void tidy() {
        sort_unique(pairs_);
        stopped_ = stopped_ || pairs_.size() >= kMostCountedPairs;
        next_tidy_ = pairs_.size() + kMostCountedPairs;
    }

    void keep_if_lowest(const FacePair& pair) {
        auto end = lowest_.begin() + kept_;
        auto at = std::lower_bound(lowest_.begin(), end, pair);
        if (at != end && *at == pair) return;
        if (kept_ < kKeptLocations) {
            ++kept_;
            ++end;
        } else if (at == end) {
            return;
        }
        std::move_backward(at, end - 1, end);
        *at = pair;
    }

    std::pmr::vector<FacePair> pairs_;  // until stopped, with repeats between tidies
    std::size_t next_tidy_ = kMostCountedPairs;
    std::array<FacePair, kKeptLocations> lowest_{};
    std::size_t kept_ = 0;
    bool stopped_ = false;
};

// How many corners two triangles share (as vertices, not positions), and
// where the last one found sits in each.
struct SharedCorners {
    int count = 0, at_first = 0, at_second = 0;
};

SharedCorners shared_corners(const std::array<std::uint32_t, 3>& first,
                             const std::array<std::uint32_t, 3>& second) {
    SharedCorners shared;
    for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l)
            if (first[k] == second[l]) shared = {shared.count + 1, k, l};
    return shared;
}

// visit(t) for each t in [0, count), in fixed blocks run as tasks: for
// passes over the triangles whose items are independent of one another.
template <class Visit>
void for_each_in_blocks(std::size_t count, TaskRunner& tasks, const Visit& visit) {
    const std::size_t blocks = (count + kFacesPerBlock - 1) / kFacesPerBlock;
    tasks.run(blocks, [&](std::size_t block) {
        const std::size_t end = std::min(count, (block + 1) * kFacesPerBlock);
        for (std::size_t t = block * kFacesPerBlock; t < end; ++t) visit(t);
    });
}

// Triangles at the same three positions in the same order: copies of a part
// stacked in place, or a surface exported twice. Copies meet every other
// triangle alike, so the search for meeting faces holds one triangle of each
// shape, and the copies of the two shapes of a pair it finds are paired
// without it: a pile of k copies is then one pair of shapes, not k^2 pairs
// of triangles each found through the tree.
inline constexpr std::uint32_t kNoCopy = UINT32_MAX;

struct Shapes {
    // Per triangle: the lowest triangle of its shape (itself when it is
    // alone), and the next copy above it, or kNoCopy.
    std::pmr::vector<std::uint32_t> lowest, next;

    explicit Shapes(std::pmr::memory_resource* memory) : lowest(memory), next(memory) {}
};

// Triangles are first sorted by a hash of their nine coordinates and then by
// index (one 64-bit key each, sorted in linear time): copies hash alike, so
// only triangles of one hash, nearly always alone, are compared coordinate by
// coordinate. Sorting every triangle by its coordinates took 40 % of the
// intersection check of a million-triangle sphere.
template <class TriangleAt>
Shapes find_shapes(std::size_t count, const TriangleAt& triangle, TaskRunner& tasks,
                   std::pmr::memory_resource* memory) {
    auto coordinates = [&](std::uint32_t t) {
        const Triangle corners = triangle(t);
        std::array<double, 9> flat;
        for (int k = 0; k < 3; ++k)
            for (int c = 0; c < 3; ++c) flat[3 * k + c] = corners[k][c];
        return flat;
    };
    // The nine coordinates' bits (position_hash.hpp: -0 as +0) mixed in order.
    auto hash = [](const std::array<double, 9>& flat) {
        std::uint64_t h = 0x9e3779b97f4a7c15u;
        for (double x : flat) {
            h = (h ^ position_bits(x)) * 0xff51afd7ed558ccdu;
            h ^= h >> 32;
        }
        return h;
    };
    std::pmr::vector<std::uint64_t> keys(count, memory);
    for_each_in_blocks(count, tasks, [&](std::size_t t) {
        keys[t] = (hash(coordinates(std::uint32_t(t))) & 0xffffffff00000000u) | t;
    });
    radix_sort(keys.data(), keys.data() + keys.size(), memory);
    auto triangle_of = [&](std::size_t k) { return std::uint32_t(keys[k]); };
    Shapes shapes(memory);
    shapes.lowest.resize(count);
    shapes.next.assign(count, kNoCopy);
    std::pmr::vector<std::pair<std::array<double, 9>, std::uint32_t>> group(memory);
    for (std::size_t k = 0; k < count;) {
        std::size_t end = k + 1;
        while (end < count && keys[end] >> 32 == keys[k] >> 32) ++end;
        if (end - k == 1) {
            shapes.lowest[triangle_of(k)] = triangle_of(k);
            k = end;
            continue;
        }
        // Triangles of one hash, in ascending index: nearly always copies
        // of one shape, whose list is then that order. Otherwise (hashes
        // that collide) by coordinates, then index.
        group.clear();
        for (std::size_t m = k; m < end; ++m)
            group.push_back({coordinates(triangle_of(m)), triangle_of(m)});
        const bool one_shape = std::all_of(group.begin(), group.end(), [&](const auto& member) {
            return member.first == group.front().first;
        });
        if (!one_shape) std::sort(group.begin(), group.end());
        for (std::size_t first = 0; first < group.size();) {
            std::size_t last = first + 1;
            while (last < group.size() && group[last].first == group[first].first) ++last;
            for (std::size_t m = first; m < last; ++m) {
                shapes.lowest[group[m].second] = group[first].second;
                if (m + 1 < last) shapes.next[group[m].second] = group[m + 1].second;
            }
            first = last;
        }
        k = end;
    }
    return shapes;
}

}  // namespace

template <class Scalar, class Index>
SurfaceOverlaps find_overlaps(const MeshView<Scalar, Index>& mesh, const std::uint32_t* vertex_ids,
                              const Eigen::Vector3d& reference, double size, const Shells* shells,
                              TaskRunner& tasks, std::pmr::memory_resource* memory) {
    SurfaceOverlaps result(memory);
    SurfaceTriangles triangles = triangulate_faces(mesh, memory);
    // Each corner as the vertex it is welded to, in place: the test of shared
    // corners reads nothing else for most candidate pairs.
    auto& ids = triangles.corners;
    if (vertex_ids)
        for (auto& corners : ids)
            for (std::uint32_t& vertex : corners) vertex = vertex_ids[vertex];
    // The surface as the topology check saw it: a welded vertex at the
    // position of the vertex it was welded to, so that corners the surface
    // shares are the same point, not two points 1e-17 apart whose triangles
    // would seem to cross.
    // Corner `first` first, keeping the triangle's turn.
    auto triangle = [&](std::size_t t, int first = 0) {
        return Triangle{mesh.positions[ids[t][first]], mesh.positions[ids[t][(first + 1) % 3]],
                        mesh.positions[ids[t][(first + 2) % 3]]};
    };
    // The tree's boxes are in a power-of-two unit near the surface's size, so
    // that single precision holds them for any size a double does.
    const double per_unit = 1.0 / unit_length_near(size);
    auto in_units = [&](const Eigen::Vector3d& p) -> Eigen::Vector3d {
        return (p - reference) * per_unit;
    };

    // Degenerate triangles keep an empty box: they bound nothing and meet nothing.
    std::pmr::vector<FloatBox> boxes(triangles.size(), memory);
    for_each_in_blocks(triangles.size(), tasks, [&](std::size_t t) {
        const Triangle corners = triangle(t);
        if (is_degenerate(corners)) return;
        for (const Eigen::Vector3d& corner : corners) boxes[t].extend(in_units(corner));
    });
    // The tree holds the lowest triangle of each shape: the copies above it
    // keep an empty box too, and are met through it. (Found after the boxes,
    // so that the tree's scratch reuses the search's: 8 MB less at the peak
    // of a million triangles.)
    const Shapes shapes = find_shapes(triangles.size(), triangle, tasks, memory);
    for_each_in_blocks(triangles.size(), tasks, [&](std::size_t t) {
        if (shapes.lowest[t] != t) boxes[t] = FloatBox();
    });
    auto meets_nothing = [&](std::size_t t) {
        const FloatBox& box = boxes[shapes.lowest[t]];
        return !(box.lo[0] <= box.hi[0]);
    };
    FloatBox everything;
    for (const FloatBox& box : boxes) everything.extend(box);
    const BoxTree tree(boxes, memory);

    const bool nesting = shells && shells->count >= 2;
    const auto shell_of = [&](std::size_t t) { return shells->of_face[triangles.face[t]]; };
    // Per shape (its lowest triangle): whether it touches a triangle of
    // another shell. Only there can the rest of the surface wind around a
    // shell otherwise than at its probe vertex (the nesting, below). Copies
    // on two shells coincide, which is crossing and ends the check before the
    // nesting, so the copies of a shape that matters lie on one shell.
    std::pmr::vector<std::atomic<std::uint8_t>> touches_other_shell(nesting ? triangles.size() : 0,
                                                                    memory);
    auto note_contact = [&](Contact contact, std::uint32_t i, std::uint32_t j) {
        if (contact == Contact::touching && nesting && shell_of(i) != shell_of(j)) {
            touches_other_shell[shapes.lowest[i]].store(1, std::memory_order_relaxed);
            touches_other_shell[shapes.lowest[j]].store(1, std::memory_order_relaxed);
        }
    };

    // Adds the face pair of triangles i and j as its contact says. Coinciding
    // triangles of two shells bound the region behind both twice, as crossing
    // ones do; within one shell they may be a fan over a non-convex polygon,
    // whose overlaps cancel, and are taken as touching (so too without shells:
    // the surface is then refused on other grounds).
    auto add = [&](Contact contact, std::uint32_t i, std::uint32_t j, const FacePair& pair,
                   PairCollector& crossing, PairCollector& touching) {
        if (contact == Contact::coinciding)
            contact = shells && shell_of(i) != shell_of(j) ? Contact::crossing : Contact::touching;
        note_contact(contact, i, j);
        if (contact != Contact::none)
            (contact == Contact::crossing ? crossing : touching).add(pair);
    };
    // Triangles sharing two corners are neighbours across an edge and meet
    // nothing more, and so are those sharing three in opposite turns (a face
    // beside its reverse: a sheet of no thickness, which cancels). Three in
    // one turn are one triangle written twice, which bounds the region behind
    // it twice (a surface welded to its copy and accepted as non-manifold):
    // crossing, whatever the shells. Returns whether the shared corners
    // decided the pair; the contact test decides every other.
    auto decided_by_shared_corners = [&](std::uint32_t i, std::uint32_t j,
                                         const SharedCorners& shared, const FacePair& pair,
                                         PairCollector& crossing) {
        if (shared.count < 2) return false;
        if (shared.count == 3 &&
            ids[i][(shared.at_first + 1) % 3] == ids[j][(shared.at_second + 1) % 3])
            crossing.add(pair);
        return true;
    };
    // Triangles i and j, of different faces.
    auto test_pair = [&](std::uint32_t i, std::uint32_t j, PairCollector& crossing,
                         PairCollector& touching) {
        const std::uint32_t face_i = triangles.face[i], face_j = triangles.face[j];
        if (face_i == face_j) return;  // pieces of one polygon
        const FacePair pair{std::min(face_i, face_j), std::max(face_i, face_j)};
        // Past the stop of touching pairs a pair is still tested while the
        // count of crossing ones wants it, which it does until 2048 cross:
        // every touching pair that the nesting needs is marked.
        if (!crossing.wants(pair) && !touching.wants(pair)) return;
        const SharedCorners shared = shared_corners(ids[i], ids[j]);
        if (decided_by_shared_corners(i, j, shared, pair, crossing)) return;
        // The shared corner first.
        add(triangle_contact(triangle(i, shared.at_first), triangle(j, shared.at_second),
                             shared.count == 1),
            i, j, pair, crossing, touching);
    };
    // The pairs of copies of shapes r and s (r != s), or of two distinct
    // copies of r (r == s). Which corners a pair shares decides its contact:
    // none, or corner k of one with corner l of the other, which then lie at
    // one position, so each such pattern is tested once, when first met. The
    // copies of a shape ascend, and their faces with them, so along a row (j)
    // the face pairs only grow: the first that no collector wants ends the
    // row, and so does the first that only collectors of kinds no pattern
    // gives want: past the count's stop a pile costs a test per copy, not
    // per pair of copies.
    auto pair_copies = [&](std::uint32_t r, std::uint32_t s, PairCollector& crossing,
                           PairCollector& touching) {
        if (r != s && shapes.next[r] == kNoCopy && shapes.next[s] == kNoCopy) {
            test_pair(r, s, crossing, touching);
            return;
        }
        // [0]: no corner shared; [1 + 3 k + l]: corner k of r's copy is corner l of s's.
        std::array<Contact, 10> contact_of;
        std::array<bool, 10> tested{};
        auto contact = [&](int k, int l, bool shared_corner) {
            const int pattern = shared_corner ? 1 + 3 * k + l : 0;
            if (!tested[pattern]) {
                contact_of[pattern] =
                    triangle_contact(triangle(r, k), triangle(s, l), shared_corner);
                tested[pattern] = true;
            }
            return contact_of[pattern];
        };
        // Copies of shapes on two shells share no corner: all meet as r and
        // s do. (A row breaks past the stop of touching pairs, and copies on
        // one shell, on distinct vertices, reach the nesting.)
        if (r != s && nesting && shell_of(r) != shell_of(s))
            note_contact(contact(0, 0, false), r, s);
        for (std::uint32_t i = r; i != kNoCopy; i = shapes.next[i]) {
            for (std::uint32_t j = r == s ? shapes.next[i] : s; j != kNoCopy; j = shapes.next[j]) {
                const std::uint32_t face_i = triangles.face[i], face_j = triangles.face[j];
                if (face_i == face_j) continue;
                const FacePair pair{std::min(face_i, face_j), std::max(face_i, face_j)};
                const bool cross_wants = crossing.wants(pair), touch_wants = touching.wants(pair);
                if (!cross_wants && !touch_wants) break;
                if (!(cross_wants && touch_wants)) {
                    // Any pattern's kind is that of no corner shared, or
                    // none: a shared corner changes no crossing (the
                    // triangles' places decide it) and only drops touching
                    // and coinciding. Coinciding copies count as crossing
                    // or touching, as their shells say.
                    const Contact apart = contact(0, 0, false);
                    const bool can_cross =
                        apart == Contact::crossing || apart == Contact::coinciding;
                    const bool can_touch =
                        apart == Contact::touching || apart == Contact::coinciding;
                    if (!(can_cross && cross_wants) && !(can_touch && touch_wants)) break;
                }
                const SharedCorners shared = shared_corners(ids[i], ids[j]);
                if (decided_by_shared_corners(i, j, shared, pair, crossing)) continue;
                add(contact(shared.at_first, shared.at_second, shared.count == 1), i, j, pair,
                    crossing, touching);
            }
        }
    };

    // The contacts of one piece of the search, found on any thread.
    struct PieceContacts {
        PairCollector crossing, touching;
    };
    const std::pmr::vector<BoxTree::PairTask> pieces = tree.pair_tasks();
    std::pmr::vector<PieceContacts> found(memory);
    found.reserve(pieces.size() + 1);
    for (std::size_t piece = 0; piece <= pieces.size(); ++piece)
        found.push_back({PairCollector(memory), PairCollector(memory)});
    tasks.run(pieces.size(), [&](std::size_t piece) {
        tree.for_each_overlapping_pair(pieces[piece], [&](std::uint32_t r, std::uint32_t s) {
            pair_copies(r, s, found[piece].crossing, found[piece].touching);
        });
    });
    // The copies of one shape meet each other; the tree holds one of them.
    for (std::uint32_t t = 0; t < triangles.size(); ++t)
        if (shapes.lowest[t] == t && shapes.next[t] != kNoCopy && !meets_nothing(t))
            pair_copies(t, t, found.back().crossing, found.back().touching);
    // In piece order, though the result does not depend on it.
    PairCollector crossing(memory), touching(memory);
    for (const PieceContacts& piece : found) {
        crossing.merge(piece.crossing);
        touching.merge(piece.touching);
    }
    // Faces that cross somewhere are listed as crossing only.
    result.crossing = crossing.finding();
    result.touching = touching.finding(&crossing);
    if (!shells || shells->count < 2 || result.crossing.count > 0) return result;

    // Nesting. The probes' far ends lie outside every box.
    double span = 0;
    for (int k = 0; k < 3; ++k)
        span = std::max(span, double(everything.hi[k]) - double(everything.lo[k]));
    span /= per_unit;
    result.winding_of_shell.assign(shells->count, kUnknownWinding);
    if (!(span > 0) || !std::isfinite(4 * span)) return result;

    // The winding number of every shell but `shell` at a start that lies on
    // no other shell, or kUnknownWinding when the segment from it to
    // p + 4 span direction grazes an edge, a vertex or a plane.
    auto winding_at = [&](const ProbeStart& start, const Eigen::Vector3d& direction,
                          std::uint32_t shell) {
        const Eigen::Vector3d& p = start.p;
        const Eigen::Vector3d q = p + 4 * span * direction.normalized();
        int winding = 0;
        bool counted = true;
        tree.for_each_item_near_segment(in_units(p), in_units(q), [&](std::uint32_t t) {
            // t and its copies, of the other shells. The first graze ends
            // the walk: a pile of k shells at one place then costs each
            // probe a triangle, not k.
            int others = 0;
            for (std::uint32_t copy = t; copy != kNoCopy; copy = shapes.next[copy])
                others += shell_of(copy) != shell;
            if (others == 0) return true;
            const Triangle c = triangle(t);
            const int to = orient3d(c[0], c[1], c[2], q);
            const int from = sign_at(
                start, [&](const Eigen::Vector3d& x) { return orient3d(c[0], c[1], c[2], x); });
            // A start on c was turned away before (on_another_shell): from
            // = 0 is a start in c's plane beside it.
            if (to == 0) {
                counted = false;
                return false;
            }
            if (from == 0 || from == to) return true;
            auto edge_sign = [&](int k) {
                return sign_at(start, [&](const Eigen::Vector3d& x) {
                    return orient3d(x, q, c[k], c[(k + 1) % 3]);
                });
            };
            const int e0 = edge_sign(0), e1 = edge_sign(1), e2 = edge_sign(2);
            const bool some_positive = e0 > 0 || e1 > 0 || e2 > 0;
            const bool some_negative = e0 < 0 || e1 < 0 || e2 < 0;
            if (some_positive && some_negative) return true;  // passes beside the triangle
            if (e0 == 0 || e1 == 0 || e2 == 0) {
                counted = false;  // through an edge or a corner
                return false;
            }
            winding += from < 0 ? others : -others;  // leaving through the faces' outer side
            return true;
        });
        return counted ? winding : kUnknownWinding;
    };

    // A few triangles of each shell, in order, whose first corners are the probes.
    std::pmr::vector<std::array<std::uint32_t, kProbeVertices>> probes(shells->count, memory);
    std::pmr::vector<std::uint8_t> probe_count(shells->count, 0, memory);
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        const std::uint32_t shell = shell_of(t);
        if (!meets_nothing(t) && probe_count[shell] < kProbeVertices)
            probes[shell][probe_count[shell]++] = std::uint32_t(t);
    }
    // Whether the start lies on another shell's triangle: a look at the few
    // triangles whose boxes hold it, before long probes that would only graze
    // there. The vertices of parts resting on each other often do, and the
    // starts next to the corners of faces resting flush always do.
    auto on_another_shell = [&](const ProbeStart& start, std::uint32_t shell) {
        bool on = false;
        tree.for_each_item_near_segment(in_units(start.p), in_units(start.p), [&](std::uint32_t t) {
            if (shell_of(t) == shell) return true;
            const Triangle c = triangle(t);
            on = sign_at(start,
                         [&](const Eigen::Vector3d& x) { return orient3d(c[0], c[1], c[2], x); }) ==
                     0 &&
                 lies_on(c, start);
            return !on;
        });
        return on;
    };
    // The winding at the start, or kUnknownWinding when it lies on another
    // shell or every direction grazes.
    auto probe = [&](const ProbeStart& start, std::uint32_t shell) {
        int winding = kUnknownWinding;
        if (on_another_shell(start, shell)) return winding;
        for (const Eigen::Vector3d& direction : kProbeDirections) {
            winding = winding_at(start, direction, shell);
            if (winding != kUnknownWinding) break;
        }
        return winding;
    };
    for (std::uint32_t shell = 0; shell < shells->count; ++shell) {
        int& winding = result.winding_of_shell[shell];
        for (std::size_t k = 0; k < probe_count[shell] && winding == kUnknownWinding; ++k) {
            const Eigen::Vector3d p = mesh.positions[ids[probes[shell][k]][0]];
            winding = probe({p, p, p, false}, shell);
        }
    }
    // Where a shell touches another, the rest of the surface may wind around
    // its pieces differently: a surface passing through another's face
    // exactly along its own edges crosses no face, yet lies partly inside
    // the other part, and all its vertices may lie on that part or outside
    // it. So each triangle touching another shell is probed from inside,
    // next to each of its corners, unless the start there lies on another
    // shell (what touches it from one side, along a segment or at a point,
    // leaves the winding alike on both sides; a face lying flush on part of
    // it cuts its inside into pieces, which these probes reach unless flush
    // faces cover every corner); a shell whose probes disagree bounds some
    // region twice (or less than once), whatever its sense.
    for (std::uint32_t t = 0; t < triangles.size(); ++t) {
        if (!touches_other_shell[t].load(std::memory_order_relaxed)) continue;
        const std::uint32_t shell = shell_of(t);
        int& winding = result.winding_of_shell[shell];
        for (int k = 0; k < 3 && winding != kMixedWinding; ++k) {
            const Triangle corners = triangle(t, k);
            const int here = probe({corners[0], corners[1], corners[2], true}, shell);
            if (here != kUnknownWinding)
                winding = winding == kUnknownWinding || winding == here ? here : kMixedWinding;
        }
    }
    return result;
}

#define POLYMASS_INSTANTIATE(Scalar, Index)                                                   \
    template SurfaceOverlaps find_overlaps<Scalar, Index>(                                    \
        const MeshView<Scalar, Index>&, const std::uint32_t*, const Eigen::Vector3d&, double, \
        const Shells*, TaskRunner&, std::pmr::memory_resource*);
POLYMASS_FOR_EACH_MESH_VIEW(POLYMASS_INSTANTIATE)
#undef POLYMASS_INSTANTIATE

}  // namespace polymass::core
