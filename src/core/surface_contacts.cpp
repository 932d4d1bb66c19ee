#include "surface_contacts.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <mutex>
#include <optional>
#include <utility>

#include "leaf_corners.hpp"
#include "shell_pairs.hpp"
#include "triangle_contact.hpp"

namespace polymass::core {
namespace {

using FacePair = std::array<std::uint64_t, 2>;

void sort_unique(std::pmr::vector<FacePair>& pairs) {
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
}

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

    // Takes in what another piece of the search collected. Tidied when
    // add() would be, not at each piece: a sort of all the pairs so far at
    // each of a crossing surface's hundreds of pieces was an eighth of its
    // check.
    void merge(const PairCollector& piece) {
        for (std::size_t i = 0; i < piece.kept_; ++i) keep_if_lowest(piece.lowest_[i]);
        if (stopped_) return;
        pairs_.insert(pairs_.end(), piece.pairs_.begin(), piece.pairs_.end());
        stopped_ = piece.stopped_;
        if (pairs_.size() >= next_tidy_) tidy();
    }

    // The pairs counted, without those `except` holds. Past the stop the
    // count is a lower bound (complete false).
    PairFinding finding(const PairCollector* except = nullptr) {
        tidy();
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

    // Whether no pair was added.
    bool empty() const { return kept_ == 0; }

    // Whether the count has stopped: kMostCountedPairs distinct pairs were
    // added (seen at the latest when as many more have come).
    bool stopped() const { return stopped_; }

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

// Where the search along the tree ends: at the first piece, in piece order,
// at which the crossing pairs of the pieces up to it reach the count's stop.
// The surface is refused then whatever the rest holds, and a pile of parts
// crossing each other everywhere (near copies, each turned a little) meets
// in a number of pairs that grows with the square of the parts: the search
// that went on to give the lowest pairs of all was quadratic there (800
// cubes, 9,600 triangles: 9.5 s). The pieces past the end are not
// searched, or their findings dropped when they ran at the same time; each
// piece's findings depend on the piece alone (a piece stops at its own
// count's stop, whose pairs already end the search there), so the end, and
// the finding, are the same on any number of threads.
class SearchEnd {
public:
    SearchEnd(std::size_t pieces, std::pmr::memory_resource* memory)
        : searched_(pieces, 0, memory), crossing_(memory), end_(pieces) {}

    // Whether piece lies past the end found so far: it need not be searched.
    bool past(std::size_t piece) const { return piece >= end_.load(std::memory_order_relaxed); }

    // Takes in the crossing pairs of a searched piece once those of every
    // piece before it are in, and ends the search where they stop.
    template <class CrossingOf>
    void searched(std::size_t piece, const CrossingOf& crossing_of) {
        const std::lock_guard<std::mutex> lock(mutex_);
        searched_[piece] = 1;
        for (; next_ < searched_.size() && searched_[next_] && !crossing_.stopped(); ++next_) {
            crossing_.merge(crossing_of(next_));
            if (crossing_.stopped()) end_.store(next_ + 1, std::memory_order_relaxed);
        }
    }

    // How many pieces, from the first, the finding holds.
    std::size_t end() const { return end_.load(std::memory_order_relaxed); }

private:
    std::mutex mutex_;
    std::pmr::vector<std::uint8_t> searched_;
    PairCollector crossing_;  // of pieces [0, next_)
    std::size_t next_ = 0;
    std::atomic<std::size_t> end_;
};

// How many corners two triangles share (as vertices, not positions), and
// where the last one found sits in each. Inlined: asked for every candidate
// pair, and GCC left it out of line once test_pair had three callers (the
// clean torus 1e5 then cost 4.4 % more instructions).
struct SharedCorners {
    int count = 0, at_first = 0, at_second = 0;
};

__attribute__((always_inline)) inline SharedCorners shared_corners(
    const std::array<std::uint32_t, 3>& first, const std::array<std::uint32_t, 3>& second) {
    SharedCorners shared;
    for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l)
            if (first[k] == second[l]) shared = {shared.count + 1, k, l};
    return shared;
}

// Whether two triangles sharing one vertex, corner k of the first (its
// corner extremes `first`, IndexedSurface::corner_extremes) and corner l of
// the second, lie on either side of a plane x = c through it on some axis:
// the highest of one there is the lowest of the other (on a surface, most
// pairs around a vertex; fetching both triangles and testing their extents
// was a third of a clean surface's search). Then they do not cross, and
// met at a shared corner only crossing counts (triangle_contact decides them
// so, from their extents): decided without their positions.
bool apart_at_shared_corner(std::uint32_t first, int k, std::uint32_t second, int l) {
    const std::uint32_t a = first >> 6 * k, b = second >> 6 * l;
    return ((a & b >> 3) | (a >> 3 & b)) & 7u;
}

// Whether two triangles, of shells boxed `first` and `second`, neither cross
// nor coincide, as the boxes say: on an axis where one box ends at or below
// where the other begins, the triangles lie on either side of a plane x = c
// (or apart), so that they do not cross, and coincide only when both lie
// flat in it (`both_flat`, bit per axis). Parts resting on each other meet
// so in most pairs, which then need neither triangle's positions. Inlined:
// GCC left it out of line, a call for each such pair.
__attribute__((always_inline)) inline bool apart_but_in_a_plane(const ShellBox& first,
                                                                const ShellBox& second,
                                                                std::uint32_t both_flat) {
    for (int axis = 0; axis < 3; ++axis) {
        const double low_end = std::min(first.hi[axis], second.hi[axis]);
        const double high_start = std::max(first.lo[axis], second.lo[axis]);
        if (low_end < high_start || (low_end == high_start && !(both_flat >> axis & 1)))
            return true;
    }
    return false;
}

}  // namespace

template <class Scalar, class Index>
SurfaceContacts find_contacts(const IndexedSurface<Scalar, Index>& surface, TaskRunner& tasks,
                              std::pmr::memory_resource* memory) {
    const Shells* shells = surface.shells();
    const bool nesting = shells && shells->count >= 2;
    const auto shell_of = [&](std::size_t t) { return shells->of_face[surface.face(t)]; };
    // Per shape (its lowest triangle): whether it touches a triangle of
    // another shell. Only there can the rest of the surface wind around a
    // shell otherwise than at its probe vertex (the nesting, below). Copies
    // on two shells coincide, which is crossing and ends the check before the
    // nesting, so the copies of a shape that matters lie on one shell.
    SurfaceContacts contacts(nesting ? surface.size() : 0, memory);
    auto& touches_other_shell = contacts.touches_other_shell;
    if (nesting) contacts.reached_inside = shells_reached_inside(surface, tasks, memory);
    const auto& reached_inside = contacts.reached_inside;
    const std::pmr::vector<ShellBox>& shell_boxes = surface.shell_boxes();
    // Whether triangle t of shell `shell` is of a shell that another may
    // wind around, not yet marked: only such a triangle's touching matters
    // to the nesting. A mark read unset by a race only costs a test.
    auto needs_mark = [&](std::uint32_t t, std::uint32_t shell) {
        return reached_inside[shell] &&
               !touches_other_shell[surface.lowest_copy(t)].load(std::memory_order_relaxed);
    };
    auto note_contact = [&](Contact contact, std::uint32_t i, std::uint32_t j) {
        if (contact != Contact::touching || !nesting || shell_of(i) == shell_of(j)) return;
        for (const std::uint32_t t : {i, j})
            if (reached_inside[shell_of(t)])
                touches_other_shell[surface.lowest_copy(t)].store(1, std::memory_order_relaxed);
    };

    // Whether telling touching from none, for the pair of triangles i and j
    // (their faces `pair`), could change the finding: the touching pairs
    // still want it, or it would mark a triangle touching another shell
    // that needs a mark. Past the stop of touching pairs, an assembly
    // resting on itself has every triangle that needs one marked by its
    // first touching pair (and parts resting on each other in a grid need
    // none), and its other pairs need only say whether they cross.
    auto touching_matters = [&](std::uint32_t i, std::uint32_t j, const FacePair& pair,
                                const PairCollector& touching) {
        if (touching.wants(pair)) return true;
        if (!nesting) return false;
        const std::uint32_t shell_i = shell_of(i), shell_j = shell_of(j);
        return shell_i != shell_j && (needs_mark(i, shell_i) || needs_mark(j, shell_j));
    };

    // Per shape (its lowest triangle), with shells: whether two of its
    // copies lie on one shell.
    std::pmr::vector<std::uint8_t> copies_share_a_shell(shells ? surface.size() : 0, 0, memory);
    if (shells) {
        std::pmr::vector<std::uint32_t> last_shape_on(shells->count, kNoCopy, memory);
        for (std::uint32_t t = 0; t < surface.size(); ++t) {
            if (surface.lowest_copy(t) != t || surface.next_copy(t) == kNoCopy) continue;
            for (std::uint32_t copy = t; copy != kNoCopy; copy = surface.next_copy(copy)) {
                std::uint32_t& last = last_shape_on[shell_of(copy)];
                copies_share_a_shell[t] |= last == t;
                last = t;
            }
        }
    }

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
    // Whether the corners triangles i and j share say that they add no pair:
    // sharing two, they are neighbours across an edge and meet nothing more,
    // and so are those sharing three in opposite turns (a face beside its
    // reverse: a sheet of no thickness, which cancels); sharing one, they may
    // lie on either side of an axis plane through it (apart_at_shared_corner).
    // Three in one turn are one triangle written twice, which bounds the
    // region behind it twice (a surface welded to its copy and accepted as
    // non-manifold): crossing, whatever the shells, as decide_pair says.
    auto add_nothing = [&](std::uint32_t i, std::uint32_t j, const SharedCorners& shared) {
        switch (shared.count) {
            case 1:
                return apart_at_shared_corner(surface.corner_extremes(i), shared.at_first,
                                              surface.corner_extremes(j), shared.at_second);
            case 2:
                return true;
            case 3:
                return surface.corners(i)[(shared.at_first + 1) % 3] !=
                       surface.corners(j)[(shared.at_second + 1) % 3];
            default:
                return false;
        }
    };
    // Triangles i and j that share the corners `shared`, and which
    // add_nothing left: kept out of line, as most pairs never come here.
    auto decide_pair = [&](std::uint32_t i, std::uint32_t j, const SharedCorners& shared,
                           PairCollector& crossing, PairCollector& touching)
        __attribute__((noinline)) {
        const std::uint32_t face_i = surface.face(i), face_j = surface.face(j);
        if (face_i == face_j) return;  // pieces of one polygon
        const FacePair pair{std::min(face_i, face_j), std::max(face_i, face_j)};
        // Triangles of two shells that only rest on each other (most pairs
        // of a touching assembly), neither needing a mark: they could only
        // add a touching pair, asked first and alone.
        if (shared.count == 0 && nesting) {
            const std::uint32_t shell_i = shell_of(i), shell_j = shell_of(j);
            if (shell_i != shell_j && !needs_mark(i, shell_i) && !needs_mark(j, shell_j) &&
                apart_but_in_a_plane(shell_boxes[shell_i], shell_boxes[shell_j],
                                     flat_axes(surface.corner_extremes(i)) &
                                         flat_axes(surface.corner_extremes(j))) &&
                !touching.wants(pair))
                return;
        }
        // Past the stop of touching pairs a pair is still tested while the
        // count of crossing ones wants it, which it does until 2048 cross:
        // every touching pair that the nesting needs is marked.
        if (!crossing.wants(pair) && !touching.wants(pair)) return;
        if (shared.count == 3) {
            crossing.add(pair);  // one triangle written twice
            return;
        }
        // The shared corner first.
        const Triangle p = surface.triangle(i, shared.at_first);
        const Triangle q = surface.triangle(j, shared.at_second);
        // Sharing no corner, and neither flat on an axis: on a curved
        // surface nearly all such pairs lie each on one side of the other's
        // plane (the thin wedges about the poles of a UV sphere, 2.3 M of a
        // million-triangle sphere's 3.1 M pairs tested here), which the
        // plane filter alone certifies at half the cost of the extents and
        // the exact path. A triangle flat on an axis is a face of a CAD or
        // voxel part, mostly resting on another, which the extents decide
        // and the filter cannot: asked of every pair, it cost the 1,000
        // cubes welded into one STL 9 % more (docs/exact-predicates.md).
        if (shared.count == 0 && flat_axes(surface.corner_extremes(i)) == 0 &&
            flat_axes(surface.corner_extremes(j)) == 0 && certainly_apart(p, q))
            return;
        // One call of add: two had it left out of line.
        const Contact contact = shared.count == 0 && !touching_matters(i, j, pair, touching)
                                    ? crossing_or_coinciding(p, q)
                                    : triangle_contact(p, q, shared.count == 1);
        add(contact, i, j, pair, crossing, touching);
    };
    // Triangles i and j, neither with copies. Inlined into the search: its
    // pairs are mostly neighbours that add_nothing decides, for which a call
    // (a frame for all that the rare rest needs) was half of their cost.
    auto test_pair = [&](std::uint32_t i, std::uint32_t j, PairCollector & crossing,
                         PairCollector & touching) __attribute__((always_inline)) {
        const SharedCorners shared = shared_corners(surface.corners(i), surface.corners(j));
        if (!add_nothing(i, j, shared)) decide_pair(i, j, shared, crossing, touching);
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
        // [0]: no corner shared; [1 + 3 k + l]: corner k of r's copy is corner l of s's.
        std::array<Contact, 10> contact_of;
        std::array<bool, 10> tested{};
        auto contact = [&](int k, int l, bool shared_corner) {
            const int pattern = shared_corner ? 1 + 3 * k + l : 0;
            if (!tested[pattern]) {
                contact_of[pattern] =
                    triangle_contact(surface.triangle(r, k), surface.triangle(s, l), shared_corner);
                tested[pattern] = true;
            }
            return contact_of[pattern];
        };
        // Copies of shapes on two shells share no corner: all meet as r and
        // s do. (A row breaks past the stop of touching pairs, and copies on
        // one shell, on distinct vertices, reach the nesting.)
        if (r != s && nesting && shell_of(r) != shell_of(s))
            note_contact(contact(0, 0, false), r, s);
        // Coinciding copies count as crossing on two shells, as touching on
        // one or without shells (add); copies of one shape each on its own
        // shell (a pile of parts) never touch, so that once the count of
        // crossing ones stops, their rows end at once.
        const bool coinciding_may_cross = shells != nullptr;
        const bool coinciding_may_touch = !shells || r != s || copies_share_a_shell[r];
        for (std::uint32_t i = r; i != kNoCopy; i = surface.next_copy(i)) {
            for (std::uint32_t j = r == s ? surface.next_copy(i) : s; j != kNoCopy;
                 j = surface.next_copy(j)) {
                const std::uint32_t face_i = surface.face(i), face_j = surface.face(j);
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
                    const bool coinciding = apart == Contact::coinciding;
                    const bool can_cross =
                        apart == Contact::crossing || (coinciding && coinciding_may_cross);
                    const bool can_touch =
                        apart == Contact::touching || (coinciding && coinciding_may_touch);
                    if (!(can_cross && cross_wants) && !(can_touch && touch_wants)) break;
                }
                const SharedCorners shared = shared_corners(surface.corners(i), surface.corners(j));
                if (add_nothing(i, j, shared)) continue;
                if (shared.count == 3) {
                    crossing.add(pair);  // one triangle written twice
                    continue;
                }
                add(contact(shared.at_first, shared.at_second, shared.count == 1), i, j, pair,
                    crossing, touching);
            }
        }
    };

    // The contacts of one piece of the search, found on any thread.
    struct PieceContacts {
        PairCollector crossing, touching;
    };
    auto pieces_of = [&](std::size_t count) {
        std::pmr::vector<PieceContacts> found(memory);
        found.reserve(count);
        for (std::size_t piece = 0; piece < count; ++piece)
            found.push_back({PairCollector(memory), PairCollector(memory)});
        return found;
    };

    // The search along the triangles' tree: every pair of shapes whose boxes
    // overlap, and the copies of each shape with each other (the last piece).
    auto search_triangle_pairs = [&]() {
        surface.build_tree(tasks);
        const std::pmr::vector<BoxTree::PairTask> pieces = surface.tree().pair_tasks();
        std::pmr::vector<PieceContacts> found = pieces_of(pieces.size() + 1);
        SearchEnd end(found.size(), memory);
        auto crossing_of = [&](std::size_t piece) -> const PairCollector& {
            return found[piece].crossing;
        };
        tasks.run(pieces.size(), [&](std::size_t piece) {
            if (end.past(piece)) return;
            const BoxTree& tree = surface.tree();
            tree.for_each_overlapping_leaf_pair(
                pieces[piece], [&](std::uint32_t first, std::uint32_t second,
                                   unsigned overlapping) __attribute__((always_inline)) {
                    PieceContacts& contacts = found[piece];
                    const unsigned left =
                        overlapping & ~neighbours_adding_nothing(surface.leaf_corners(first),
                                                                 surface.leaf_corners(second));
                    tree.for_each_pair_of(
                        first, second,
                        left, [&](std::uint32_t r, std::uint32_t s) __attribute__((always_inline)) {
                            if (surface.next_copy(r) == kNoCopy && surface.next_copy(s) == kNoCopy)
                                test_pair(r, s, contacts.crossing, contacts.touching);
                            else
                                pair_copies(r, s, contacts.crossing, contacts.touching);
                        });
                    return !contacts.crossing.stopped();
                });
            end.searched(piece, crossing_of);
        });
        // The copies of one shape meet each other; the tree holds one of them.
        if (!end.past(pieces.size()))
            for (std::uint32_t t = 0; t < surface.size(); ++t)
                if (surface.lowest_copy(t) == t && surface.next_copy(t) != kNoCopy &&
                    !surface.meets_nothing(t))
                    pair_copies(t, t, found.back().crossing, found.back().touching);
        found.erase(found.begin() + std::ptrdiff_t(end.end()), found.end());
        return found;
    };

    // The search by pairs of shells (pair_shells): the triangles of each
    // shell with each other, and of two shells whose boxes meet with each
    // other where that could change the finding. Two shells whose boxes
    // meet only in a plane, a line or a point (parts resting on each
    // other) have triangles on either side of it, which do not cross, and
    // coincide only when both lie flat in it (apart_but_in_a_plane): their
    // other pairs could only touch, which matters while the touching pairs
    // want the lowest pair the two shells could give, or to mark a
    // triangle not yet marked. Past that, only those pairs are tested:
    // the ones decide_pair would not leave at its first test.
    auto search_shell_pairs = [&](const ShellPairs& paired) {
        // The lowest face of each shell's triangles: the lowest face pair
        // two shells could give is their two lowest faces.
        std::pmr::vector<std::uint32_t> lowest_face(shells->count, UINT32_MAX, memory);
        for (std::size_t s = 0; s < shells->count; ++s)
            for (std::uint32_t at = paired.first_triangle[s]; at < paired.first_triangle[s + 1];
                 ++at)
                lowest_face[s] = std::min(lowest_face[s], surface.face(paired.triangles[at]));
        // The pairs of triangles of shell s whose boxes overlap.
        auto pair_within = [&](std::uint32_t s, PieceContacts& contacts) {
            for (std::uint32_t a = paired.first_triangle[s]; a < paired.first_triangle[s + 1]; ++a)
                for (std::uint32_t b = a + 1; b < paired.first_triangle[s + 1]; ++b)
                    if (paired.boxes[a].overlaps(paired.boxes[b]))
                        test_pair(paired.triangles[a], paired.triangles[b], contacts.crossing,
                                  contacts.touching);
        };
        // A triangle of a shell whose box meets another shell's.
        struct Near {
            std::uint32_t at;  // in paired.triangles
            bool marked;
            std::uint32_t flat;  // flat_axes
            int turn;            // turn_along the axis flat_on, when listed so
        };
        // Those flat on the axis `flat_on` only (one bit), with their turn
        // along it, when that is not 0.
        auto near_other = [&](std::uint32_t s, std::uint32_t t, std::uint32_t flat_on,
                              std::pmr::vector<Near>& near) {
            near.clear();
            for (std::uint32_t at = paired.first_triangle[s]; at < paired.first_triangle[s + 1];
                 ++at) {
                if (!paired.boxes[at].overlaps(paired.shell_boxes[t])) continue;
                const std::uint32_t i = paired.triangles[at];
                const std::uint32_t flat = flat_axes(surface.corner_extremes(i));
                if ((flat & flat_on) != flat_on) continue;
                const int turn =
                    flat_on != 0 ? turn_along(surface.triangle(i), __builtin_ctz(flat_on)) : 0;
                near.push_back({at, !needs_mark(i, s), flat, turn});
            }
        };
        // The pairs of triangles of shells s and t whose boxes overlap (a
        // triangle whose box misses the other shell's meets none of its
        // triangles). When only touching is left to learn from them (the
        // boxes meet in a plane, a line or a point: the axes `resting`, and
        // the touching pairs are full), only the pairs of which a triangle
        // is not yet marked, or both lie flat in that plane (a triangle flat
        // on two axes is degenerate: none when the boxes meet in a line or a
        // point). A mark read before it was set only costs a test. Where
        // neither shell's triangles need marks (parts resting on each other
        // in a grid), only the triangles flat in that plane are listed, and
        // only those turning alike paired: flat in one plane, two triangles
        // that turn opposite ways (faces resting on each other) only touch.
        auto pair_between = [&](std::uint32_t s, std::uint32_t t, std::uint32_t resting,
                                PieceContacts& contacts, std::pmr::vector<Near>& of_s,
                                std::pmr::vector<Near>& of_t) {
            const std::uint32_t flat_on =
                resting != 0 && !reached_inside[s] && !reached_inside[t] ? resting : 0;
            if ((flat_on & (flat_on - 1)) != 0) return;  // a line or a point
            near_other(s, t, flat_on, of_s);
            if (of_s.empty()) return;
            near_other(t, s, flat_on, of_t);
            for (const Near& first : of_s)
                for (const Near& second : of_t)
                    if ((resting == 0 || !first.marked || !second.marked ||
                         (first.flat & second.flat) == resting) &&
                        first.turn == second.turn &&
                        paired.boxes[first.at].overlaps(paired.boxes[second.at]))
                        test_pair(paired.triangles[first.at], paired.triangles[second.at],
                                  contacts.crossing, contacts.touching);
        };
        auto pair_shells_met = [&](std::uint32_t s, std::uint32_t t, PieceContacts& contacts,
                                   std::pmr::vector<Near>& of_s, std::pmr::vector<Near>& of_t) {
            const ShellBox &first = shell_boxes[s], &second = shell_boxes[t];
            std::uint32_t meeting_in_a_plane = 0;  // bit per axis
            for (int axis = 0; axis < 3; ++axis)
                if (std::min(first.hi[axis], second.hi[axis]) ==
                    std::max(first.lo[axis], second.lo[axis]))
                    meeting_in_a_plane |= 1u << axis;
            const FacePair lowest{std::min(lowest_face[s], lowest_face[t]),
                                  std::max(lowest_face[s], lowest_face[t])};
            const bool only_touching_to_learn =
                meeting_in_a_plane != 0 && !contacts.touching.wants(lowest);
            pair_between(s, t, only_touching_to_learn ? meeting_in_a_plane : 0, contacts, of_s,
                         of_t);
        };
        // Pieces of whole shells, each the first to reach kTrianglesPerPiece
        // triangles: cut by the surface alone, as the tree's are. Each
        // counts its own touching pairs, so that a piece of too few
        // triangles never reaches the stop of its count and enters every
        // pair of shells (pieces of 64 shells of 1,000 cubes: 305 M
        // instructions of find_contacts, against the tree's 357 M).
        constexpr std::size_t kTrianglesPerPiece = 4096;
        std::pmr::vector<std::uint32_t> piece_ends(memory);  // in shells
        for (std::uint32_t s = 0, start = 0; s < shells->count; ++s)
            if (paired.first_triangle[s + 1] - start >= kTrianglesPerPiece ||
                s + 1 == shells->count) {
                piece_ends.push_back(s + 1);
                start = paired.first_triangle[s + 1];
            }
        // A crossing pair found anywhere sends the surface to the tree's
        // search (below): the pieces stop at the first.
        std::atomic<bool> crossing_found{false};
        std::pmr::vector<PieceContacts> found = pieces_of(piece_ends.size());
        tasks.run(piece_ends.size(), [&](std::size_t piece) {
            std::pmr::vector<Near> of_s(memory), of_t(memory);
            for (std::uint32_t s = piece == 0 ? 0 : piece_ends[piece - 1]; s < piece_ends[piece];
                 ++s) {
                if (crossing_found.load(std::memory_order_relaxed)) return;
                pair_within(s, found[piece]);
                for (std::uint32_t at = paired.first_partner[s]; at < paired.first_partner[s + 1];
                     ++at)
                    pair_shells_met(s, paired.partners[at], found[piece], of_s, of_t);
                if (!found[piece].crossing.empty())
                    crossing_found.store(true, std::memory_order_relaxed);
            }
        });
        return found;
    };

    // By pairs of shells when they serve; but a surface with crossing faces
    // is searched again along the tree (its marks cleared), for the pairs
    // each kind counts past its stop, and so the touching pairs left when
    // the crossing ones are taken out of them, depend on the order in which
    // pairs come: the answer stays the tree's.
    std::optional<std::pmr::vector<PieceContacts>> found;
    if (const std::optional<ShellPairs> paired = pair_shells(surface, tasks, memory)) {
        found = search_shell_pairs(*paired);
        const bool crossing =
            std::any_of(found->begin(), found->end(),
                        [](const PieceContacts& piece) { return !piece.crossing.empty(); });
        if (crossing) {
            found.reset();
            for (auto& mark : touches_other_shell) mark.store(0, std::memory_order_relaxed);
        }
    }
    if (!found) found = search_triangle_pairs();
    // In piece order, though the result does not depend on it.
    PairCollector crossing(memory), touching(memory);
    for (const PieceContacts& piece : *found) {
        crossing.merge(piece.crossing);
        touching.merge(piece.touching);
    }
    // Faces that cross somewhere are listed as crossing only.
    contacts.crossing = crossing.finding();
    contacts.touching = touching.finding(&crossing);
    // Past the crossing pairs' stop the search ended: touching pairs may lie
    // in what it left.
    contacts.touching.complete = contacts.touching.complete && contacts.crossing.complete;
    return contacts;
}

#define POLYMASS_INSTANTIATE(Scalar, Index)                \
    template SurfaceContacts find_contacts<Scalar, Index>( \
        const IndexedSurface<Scalar, Index>&, TaskRunner&, std::pmr::memory_resource*);
POLYMASS_FOR_EACH_MESH_VIEW(POLYMASS_INSTANTIATE)
#undef POLYMASS_INSTANTIATE

}  // namespace polymass::core
