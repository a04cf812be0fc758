// shitsukan/geom/isotropic_remesh.cpp — split, collapse, flip, smooth, project (see header).
#include "shitsukan/geom/isotropic_remesh.hpp"
#include "shitsukan/core/detmath.hpp"

#include <cmath>
#include <vector>

#include "shitsukan/geom/mesh_topology.hpp"

namespace shitsukan {

namespace {

inline int next_he(int h) { return h % 3 == 2 ? h - 2 : h + 1; }
inline int prev_he(int h) { return h % 3 == 0 ? h + 2 : h - 1; }

constexpr double kDegenerate = 1e-10;  // |cross| <= kDegenerate·(longest edge)^2

// The checks shared by the remesher and mesh_quality: finite positions, no degenerate
// triangle, manifold (the twins come back in *opposite).
Status check_input(const TriangleMesh& mesh, std::vector<int>* opposite) {
    if (mesh.indices.size() % 3 != 0)
        return Status::error(StatusCode::invalid_argument,
                             "mesh: %zu indices is not a multiple of 3", mesh.indices.size());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v)
        if (!is_finite(mesh.positions[v]))
            return Status::error(StatusCode::invalid_argument,
                                 "mesh: vertex %zu is not finite (NaN or inf)", v);
    SHITSUKAN_TRY(halfedge_opposites(mesh.indices.data(), mesh.triangle_count(),
                                     mesh.vertex_count(), *opposite));
    for (int t = 0; t < mesh.triangle_count(); ++t) {
        Vec3 a = mesh.positions[mesh.indices[3 * t]], b = mesh.positions[mesh.indices[3 * t + 1]],
             c = mesh.positions[mesh.indices[3 * t + 2]];
        double l2 =
            std::fmax(double(length_squared(b - a)),
                      std::fmax(double(length_squared(c - b)), double(length_squared(a - c))));
        if (!(double(length(cross(b - a, c - a))) > kDegenerate * l2))
            return Status::error(StatusCode::degenerate,
                                 "mesh: triangle %d is degenerate (zero area: (%g, %g, %g), "
                                 "(%g, %g, %g), (%g, %g, %g))",
                                 t, double(a.x), double(a.y), double(a.z), double(b.x), double(b.y),
                                 double(b.z), double(c.x), double(c.y), double(c.z));
    }
    return Status::success();
}

double triangle_min_angle(Vec3 a, Vec3 b, Vec3 c) {
    auto angle = [](Vec3 p, Vec3 q, Vec3 r) {  // at p
        Vec3 u = q - p, v = r - p;
        return det_atan2(double(length(cross(u, v))), double(dot(u, v)));
    };
    double m = angle(a, b, c);
    m = std::fmin(m, angle(b, c, a));
    return std::fmin(m, angle(c, a, b)) * 180.0 / kPiD;
}

Status measure(const TriangleMesh& mesh, const std::vector<int>& opp, MeshQuality* q) {
    *q = MeshQuality{};
    q->triangles = mesh.triangle_count();
    std::vector<char> used(mesh.positions.size(), 0), on_boundary(mesh.positions.size(), 0);
    double sum = 0, sum2 = 0;
    long edges = 0;
    q->edge_length_min = 1e300;
    q->min_angle_degrees = 180;
    long good = 0;
    for (int t = 0; t < q->triangles; ++t) {
        Vec3 p[3];
        for (int k = 0; k < 3; ++k) {
            std::uint32_t v = mesh.indices[3 * t + k];
            used[v] = 1;
            p[k] = mesh.positions[v];
        }
        for (int k = 0; k < 3; ++k) {
            int h = 3 * t + k, o = opp[std::size_t(h)];
            if (o < 0) {
                on_boundary[mesh.indices[std::size_t(h)]] = 1;
                on_boundary[mesh.indices[std::size_t(next_he(h))]] = 1;
            }
            if (o >= 0 && o < h) continue;  // each edge once
            double l = double(length(p[(k + 1) % 3] - p[k]));
            sum += l;
            sum2 += l * l;
            ++edges;
            q->edge_length_min = std::fmin(q->edge_length_min, l);
            q->edge_length_max = std::fmax(q->edge_length_max, l);
        }
        double a = triangle_min_angle(p[0], p[1], p[2]);
        q->min_angle_degrees = std::fmin(q->min_angle_degrees, a);
        good += a > 25.0;
        q->area += 0.5 * double(length(cross(p[1] - p[0], p[2] - p[0])));
    }
    for (std::size_t v = 0; v < used.size(); ++v) {
        q->vertices += used[v];
        q->boundary_vertices += on_boundary[v];
    }
    if (edges > 0) {
        q->edge_length_mean = sum / double(edges);
        double var = sum2 / double(edges) - q->edge_length_mean * q->edge_length_mean;
        q->edge_length_cv = std::sqrt(var > 0 ? var : 0) / q->edge_length_mean;
    } else {
        q->edge_length_min = 0;
        q->min_angle_degrees = 0;
    }
    q->fraction_angle_above_25 = q->triangles > 0 ? double(good) / double(q->triangles) : 0;
    return Status::success();
}

// The working mesh: triangles as vertex triples, half-edge h = 3t + k from T[h] to
// T[next(h)], twins in O (rebuilt after every sweep), locks per vertex during a sweep.
class Remesher {
public:
    Remesher(const IsotropicRemeshOptions& opt, TriangleMesh* mesh)
        : opt_(opt), P_(mesh->positions) {
        T_.assign(mesh->indices.begin(), mesh->indices.end());
        L_ = double(opt.target_edge_length);
        high_ = 4.0 / 3.0 * L_;
        low_ = 4.0 / 5.0 * L_;
        step_ = float(0.05 * L_);  // chosen here: float f is good to ~1e-6
    }

    Status run(IsotropicRemeshStats* stats) {
        SHITSUKAN_TRY(rebuild());
        for (int pass = 0; pass < opt_.passes; ++pass) {
            for (int s = 0; s < kRemeshSweeps && split_sweep(stats); ++s) SHITSUKAN_TRY(rebuild());
            // Collapses and flips keep the half-edges current: sweep until nothing changes,
            // then compact.
            bool collapsed = false;
            for (int s = 0; s < kRemeshSweeps && collapse_sweep(stats); ++s) collapsed = true;
            for (int s = 0; s < kRemeshSweeps && flip_sweep(stats); ++s) {
            }
            if (collapsed) SHITSUKAN_TRY(rebuild());
            smooth();
            project();
        }
        return Status::success();
    }

    void write(TriangleMesh* mesh) {
        mesh->positions = P_;
        mesh->indices.assign(T_.begin(), T_.end());
        mesh->normals.resize(P_.size());
        for (std::size_t v = 0; v < P_.size(); ++v) mesh->normals[v] = normal_at(P_[v]);
        mesh->uvs.clear();
        mesh->colors.clear();
    }

private:
    const IsotropicRemeshOptions& opt_;
    std::vector<Vec3> P_;
    std::vector<std::uint32_t> T_;
    std::vector<int> O_, VH_, valence_;
    std::vector<char> boundary_, lock_, dead_;
    double L_, high_, low_;
    float step_;
    // Scratch for one-rings.
    std::vector<int> ring_a_, ring_b_, tris_a_, tris_b_;
    std::vector<int> start_, fill_, out_;  // outgoing half-edges per vertex (twins())

    int tri_count() const { return int(T_.size() / 3); }
    int from(int h) const { return int(T_[std::size_t(h)]); }
    int to(int h) const { return int(T_[std::size_t(next_he(h))]); }
    float f(Vec3 p) const { return opt_.surface(p, opt_.user); }
    Vec3 normal_at(Vec3 p) const {
        return normalize(implicit_gradient(opt_.surface, opt_.user, p, step_));
    }

    // Drop dead triangles and unused vertices (keeping index order), rebuild twins, the
    // boundary flags, valences and one outgoing half-edge per vertex (the boundary one on the
    // boundary).
    Status rebuild() {
        std::vector<std::uint32_t> T;
        T.reserve(T_.size());
        for (int t = 0; t < tri_count(); ++t)
            if (dead_.empty() || !dead_[std::size_t(t)])
                for (int k = 0; k < 3; ++k) T.push_back(T_[std::size_t(3 * t + k)]);
        std::vector<int> remap(P_.size(), -1);
        for (std::uint32_t v : T) remap[v] = 0;
        int n = 0;
        for (std::size_t v = 0; v < P_.size(); ++v)
            if (remap[v] == 0) {
                remap[v] = n;
                P_[std::size_t(n++)] = P_[v];
            }
        P_.resize(std::size_t(n));
        for (std::uint32_t& v : T) v = std::uint32_t(remap[v]);
        T_.swap(T);
        twins(n);
        VH_.assign(std::size_t(n), -1);
        boundary_.assign(std::size_t(n), 0);
        valence_.assign(std::size_t(n), 0);
        for (int h = 0; h < int(T_.size()); ++h) {
            int v = from(h);
            if (VH_[std::size_t(v)] < 0) VH_[std::size_t(v)] = h;
            if (O_[std::size_t(h)] < 0) {
                VH_[std::size_t(v)] = h;
                boundary_[std::size_t(v)] = 1;
                boundary_[std::size_t(to(h))] = 1;
            }
            ++valence_[std::size_t(v)];
        }
        for (int v = 0; v < n; ++v) valence_[std::size_t(v)] += boundary_[std::size_t(v)];
        lock_.assign(std::size_t(n), 0);
        dead_.assign(std::size_t(tri_count()), 0);
        return Status::success();
    }

    // The twins of every half-edge. The input was checked by halfedge_opposites() and every
    // operation keeps the mesh manifold (the result is checked again), so this only looks up
    // b -> a for every a -> b among b's outgoing half-edges.
    void twins(int n) {
        const int halfedges = int(T_.size());
        start_.assign(std::size_t(n) + 1, 0);
        for (int h = 0; h < halfedges; ++h) ++start_[T_[std::size_t(h)] + 1];
        for (int v = 0; v < n; ++v) start_[std::size_t(v) + 1] += start_[std::size_t(v)];
        fill_.assign(start_.begin(), start_.end() - 1);
        out_.resize(std::size_t(halfedges));
        for (int h = 0; h < halfedges; ++h) out_[std::size_t(fill_[T_[std::size_t(h)]]++)] = h;
        O_.assign(std::size_t(halfedges), -1);
        for (int h = 0; h < halfedges; ++h) {
            if (O_[std::size_t(h)] >= 0) continue;
            const int a = from(h), b = to(h);
            for (int k = start_[std::size_t(b)]; k < start_[std::size_t(b) + 1]; ++k) {
                const int g = out_[std::size_t(k)];
                if (to(g) == a) {
                    O_[std::size_t(h)] = g;
                    O_[std::size_t(g)] = h;
                    break;
                }
            }
        }
    }

    // Neighbours (in fan order) and triangles around v, valid while v's fan is unchanged.
    void one_ring(int v, std::vector<int>* ring, std::vector<int>* tris) const {
        ring->clear();
        tris->clear();
        const int first = VH_[std::size_t(v)];
        int h = first;
        for (;;) {
            ring->push_back(to(h));
            tris->push_back(h / 3);
            int p = prev_he(h);
            int g = O_[std::size_t(p)];
            if (g < 0) {
                ring->push_back(from(p));  // the far end of the incoming boundary edge
                break;
            }
            if (g == first) break;
            h = g;
        }
    }

    bool locked(int v) const { return lock_[std::size_t(v)] != 0; }

    bool split_sweep(IsotropicRemeshStats* stats) {
        bool changed = false;
        const int triangles = tri_count();
        for (int h = 0; h < 3 * triangles; ++h) {
            const int o = O_[std::size_t(h)];
            if (o >= 0 && o < h) continue;
            const int a = from(h), b = to(h), c = from(prev_he(h));
            const int d = o >= 0 ? from(prev_he(o)) : -1;
            if (locked(a) || locked(b) || locked(c) || (d >= 0 && locked(d))) continue;
            if (double(length(P_[std::size_t(b)] - P_[std::size_t(a)])) <= high_) continue;
            const int m = int(P_.size());
            P_.push_back((P_[std::size_t(a)] + P_[std::size_t(b)]) * 0.5f);
            lock_.push_back(1);
            // (a, b, c) -> (a, m, c) + (m, b, c); (b, a, d) -> (b, m, d) + (m, a, d).
            T_[std::size_t(next_he(h))] = std::uint32_t(m);
            T_.insert(T_.end(), {std::uint32_t(m), std::uint32_t(b), std::uint32_t(c)});
            if (o >= 0) {
                T_[std::size_t(next_he(o))] = std::uint32_t(m);
                T_.insert(T_.end(), {std::uint32_t(m), std::uint32_t(a), std::uint32_t(d)});
                lock_[std::size_t(d)] = 1;
            }
            dead_.resize(std::size_t(tri_count()), 0);
            lock_[std::size_t(a)] = lock_[std::size_t(b)] = lock_[std::size_t(c)] = 1;
            changed = true;
            if (stats) ++stats->splits;
        }
        return changed;
    }

    // Twins glued across a removed triangle corner: x and y become each other's twins.
    void glue(int x, int y) {
        if (x >= 0) O_[std::size_t(x)] = y;
        if (y >= 0) O_[std::size_t(y)] = x;
    }

    // A valid outgoing half-edge for v, starting from any live outgoing one: on the boundary
    // the one without a twin (one_ring starts there).
    void set_vh(int v, int g) {
        const int first = g;
        for (;;) {
            if (O_[std::size_t(g)] < 0) break;
            g = next_he(O_[std::size_t(g)]);
            if (g == first) break;
        }
        VH_[std::size_t(v)] = g;
    }

    // Collapses keep the twins up to date (no locks): a -> b removes the triangles (a, b, c)
    // and (b, a, d), glues their outer edges and renames a to b around a.
    bool collapse_sweep(IsotropicRemeshStats* stats) {
        bool changed = false;
        for (int h = 0; h < int(T_.size()); ++h) {
            if (dead_[std::size_t(h / 3)]) continue;
            int o = O_[std::size_t(h)];
            if (o >= 0 && o < h) continue;
            int a = from(h), b = to(h);  // a is removed, b kept
            if (double(length(P_[std::size_t(b)] - P_[std::size_t(a)])) >= low_) continue;
            const bool edge_boundary = o < 0;
            const bool ba = boundary_[std::size_t(a)] != 0, bb = boundary_[std::size_t(b)] != 0;
            if (ba && bb && !edge_boundary) continue;
            int he = h, ho = o;  // he runs a -> b
            if (ba && !bb) {
                if (edge_boundary) continue;  // cannot happen: a boundary edge has both ends on it
                int s = a;
                a = b;
                b = s;
                he = o;
                ho = h;
            }
            const int c = from(prev_he(he)), d = edge_boundary ? -1 : from(prev_he(ho));
            // An opposite vertex keeps at least 3 neighbours.
            if (valence_[std::size_t(c)] - 1 < 3) continue;
            if (d >= 0 && valence_[std::size_t(d)] - 1 < 3) continue;
            const Vec3 p = (edge_boundary || (!ba && !bb))
                               ? (P_[std::size_t(a)] + P_[std::size_t(b)]) * 0.5f
                               : P_[std::size_t(b)];
            one_ring(a, &ring_a_, &tris_a_);
            one_ring(b, &ring_b_, &tris_b_);
            // Link condition: the common neighbours are exactly the opposite vertices.
            int common = 0;
            bool ok = true;
            for (int x : ring_a_)
                for (int y : ring_b_)
                    if (x == y) {
                        ++common;
                        if (x != c && x != d) ok = false;
                    }
            if (!ok || common != (edge_boundary ? 1 : 2)) continue;
            // New edges no longer than 4/3 L; no triangle folds over or degenerates.
            for (const std::vector<int>* ring : {&ring_a_, &ring_b_})
                for (int x : *ring)
                    if (x != a && x != b && double(length(P_[std::size_t(x)] - p)) > high_)
                        ok = false;
            for (int side = 0; side < 2 && ok; ++side) {
                const std::vector<int>& tris = side == 0 ? tris_a_ : tris_b_;
                const int moved = side == 0 ? a : b, other = side == 0 ? b : a;
                for (int t : tris) {
                    Vec3 q[3], r[3];
                    bool removed = false;
                    for (int k = 0; k < 3; ++k) {
                        int v = int(T_[std::size_t(3 * t + k)]);
                        removed |= v == other;
                        q[k] = P_[std::size_t(v)];
                        r[k] = v == moved ? p : q[k];
                    }
                    if (removed) continue;
                    Vec3 n0 = cross(q[1] - q[0], q[2] - q[0]), n1 = cross(r[1] - r[0], r[2] - r[0]);
                    double l2 = std::fmax(double(length_squared(r[1] - r[0])),
                                          std::fmax(double(length_squared(r[2] - r[1])),
                                                    double(length_squared(r[0] - r[2]))));
                    if (!(double(dot(n0, n1)) > 0.0) || !(double(length(n1)) > 1e-6 * l2))
                        ok = false;
                }
            }
            if (!ok) continue;
            // Glue the outer edges of the two removed triangles: (b->c)~(a->c), (a->d)~(b->d)
            // become twins once a is renamed b.
            const int n0 = next_he(he), p0 = prev_he(he);
            const int x0 = O_[std::size_t(n0)], y0 = O_[std::size_t(p0)];
            glue(x0, y0);
            int x1 = -1, y1 = -1;
            if (ho >= 0) {
                x1 = O_[std::size_t(next_he(ho))];
                y1 = O_[std::size_t(prev_he(ho))];
                glue(x1, y1);
                dead_[std::size_t(ho / 3)] = 1;
            }
            dead_[std::size_t(he / 3)] = 1;
            for (int t : tris_a_)
                if (!dead_[std::size_t(t)])
                    for (int k = 0; k < 3; ++k)
                        if (int(T_[std::size_t(3 * t + k)]) == a)
                            T_[std::size_t(3 * t + k)] = std::uint32_t(b);
            P_[std::size_t(b)] = p;
            boundary_[std::size_t(b)] = char(ba || bb);
            valence_[std::size_t(b)] += valence_[std::size_t(a)] - common - 2;
            --valence_[std::size_t(c)];
            if (d >= 0) --valence_[std::size_t(d)];
            valence_[std::size_t(a)] = 0;
            // Fresh outgoing half-edges for b, c, d (the old ones may have died).
            // c: c -> b (x0) or, when b -> c was a boundary edge, the edge after a -> c.
            set_vh(c, x0 >= 0 ? x0 : next_he(y0));
            if (d >= 0) set_vh(d, y1 >= 0 ? next_he(y1) : x1);
            set_vh(b, y0 >= 0 ? y0 : next_he(x0));
            changed = true;
            if (stats) ++stats->collapses;
        }
        return changed;
    }

    int deviation(int v, int delta) const {
        int e = valence_[std::size_t(v)] + delta - (boundary_[std::size_t(v)] ? 4 : 6);
        return e * e;
    }

    // Flips keep the twins up to date too.
    bool flip_sweep(IsotropicRemeshStats* stats) {
        bool changed = false;
        for (int h = 0; h < int(T_.size()); ++h) {
            if (dead_[std::size_t(h / 3)]) continue;
            const int o = O_[std::size_t(h)];
            if (o < h) continue;  // boundary edges (o < 0) never flip; each edge once
            const int a = from(h), b = to(h), c = from(prev_he(h)), d = from(prev_he(o));
            if (c == d) continue;
            const int before =
                deviation(a, 0) + deviation(b, 0) + deviation(c, 0) + deviation(d, 0);
            const int after =
                deviation(a, -1) + deviation(b, -1) + deviation(c, 1) + deviation(d, 1);
            if (after >= before) continue;
            if (valence_[std::size_t(a)] <= (boundary_[std::size_t(a)] ? 2 : 3) ||
                valence_[std::size_t(b)] <= (boundary_[std::size_t(b)] ? 2 : 3))
                continue;
            one_ring(c, &ring_a_, &tris_a_);
            bool edge_exists = false;
            for (int x : ring_a_) edge_exists |= x == d;
            if (edge_exists) continue;
            const Vec3 pa = P_[std::size_t(a)], pb = P_[std::size_t(b)], pc = P_[std::size_t(c)],
                       pd = P_[std::size_t(d)];
            const Vec3 n = cross(pb - pa, pc - pa) + cross(pa - pb, pd - pb);
            const Vec3 m0 = cross(pa - pc, pd - pc), m1 = cross(pb - pd, pc - pd);
            if (!(dot(m0, n) > 0.0f && dot(m1, n) > 0.0f && dot(m0, m1) > 0.0f)) continue;
            // (a, b, c), (b, a, d) -> (c, a, d), (d, b, c); outer twins: b->c, c->a, a->d, d->b.
            const int t0 = h / 3, t1 = o / 3;
            const int o_bc = O_[std::size_t(next_he(h))], o_ca = O_[std::size_t(prev_he(h))];
            const int o_ad = O_[std::size_t(next_he(o))], o_db = O_[std::size_t(prev_he(o))];
            const std::uint32_t tri0[3] = {std::uint32_t(c), std::uint32_t(a), std::uint32_t(d)};
            const std::uint32_t tri1[3] = {std::uint32_t(d), std::uint32_t(b), std::uint32_t(c)};
            for (int k = 0; k < 3; ++k) {
                T_[std::size_t(3 * t0 + k)] = tri0[k];
                T_[std::size_t(3 * t1 + k)] = tri1[k];
            }
            glue(3 * t0, o_ca);            // c -> a
            glue(3 * t0 + 1, o_ad);        // a -> d
            glue(3 * t0 + 2, 3 * t1 + 2);  // d -> c ~ c -> d
            glue(3 * t1, o_db);            // d -> b
            glue(3 * t1 + 1, o_bc);        // b -> c
            set_vh(c, 3 * t0);
            set_vh(a, 3 * t0 + 1);
            set_vh(d, 3 * t1);
            set_vh(b, 3 * t1 + 1);
            --valence_[std::size_t(a)];
            --valence_[std::size_t(b)];
            ++valence_[std::size_t(c)];
            ++valence_[std::size_t(d)];
            changed = true;
            if (stats) ++stats->flips;
        }
        return changed;
    }

    void smooth() {
        const float lambda = opt_.smoothing;
        std::vector<Vec3> moved(P_.size());
        for (int v = 0; v < int(P_.size()); ++v) {
            const Vec3 p = P_[std::size_t(v)];
            one_ring(v, &ring_a_, &tris_a_);
            if (boundary_[std::size_t(v)]) {
                // The two boundary neighbours: the first and the last of the fan.
                Vec3 q =
                    (P_[std::size_t(ring_a_.front())] + P_[std::size_t(ring_a_.back())]) * 0.5f;
                Vec3 np = p + (q - p) * lambda;
                np.z = p.z;
                moved[std::size_t(v)] = np;
                continue;
            }
            Vec3 centroid{0, 0, 0};
            float area = 0;
            for (int t : tris_a_) {
                Vec3 x = P_[T_[std::size_t(3 * t)]], y = P_[T_[std::size_t(3 * t + 1)]],
                     z = P_[T_[std::size_t(3 * t + 2)]];
                float w = length(cross(y - x, z - x));
                centroid += (x + y + z) * (w / 3.0f);
                area += w;
            }
            if (!(area > 0.0f)) {
                moved[std::size_t(v)] = p;
                continue;
            }
            Vec3 delta = centroid / area - p;
            Vec3 n = normal_at(p);
            delta -= n * dot(n, delta);
            moved[std::size_t(v)] = p + delta * lambda;
        }
        P_.swap(moved);
    }

    void project() {
        for (int v = 0; v < int(P_.size()); ++v) {
            Vec3 p = P_[std::size_t(v)];
            for (int s = 0; s < opt_.newton_steps; ++s) {
                Vec3 g = implicit_gradient(opt_.surface, opt_.user, p, step_);
                if (boundary_[std::size_t(v)]) g.z = 0.0f;
                float gg = dot(g, g);
                if (!(gg > 1e-12f)) break;
                p -= g * (f(p) / gg);
            }
            if (is_finite(p)) P_[std::size_t(v)] = p;
        }
    }
};

}  // namespace

Status mesh_quality(const TriangleMesh& mesh, MeshQuality& out) {
    std::vector<int> opp;
    SHITSUKAN_TRY(check_input(mesh, &opp));
    return measure(mesh, opp, &out);
}

Status isotropic_remesh(const IsotropicRemeshOptions& options, TriangleMesh& mesh,
                        IsotropicRemeshStats* stats) {
    const float L = options.target_edge_length;
    if (!is_finite(L) || !(L > 0.0f))
        return Status::error(StatusCode::invalid_argument,
                             "remesh: target_edge_length must be > 0 and finite (got %g)",
                             double(L));
    if (options.passes < 1 || options.passes > 100)
        return Status::error(StatusCode::invalid_argument,
                             "remesh: passes must be in [1, 100] "
                             "(got %d)",
                             options.passes);
    if (options.newton_steps < 0 || options.newton_steps > 20)
        return Status::error(StatusCode::invalid_argument,
                             "remesh: newton_steps must be in [0, 20] (got %d)",
                             options.newton_steps);
    if (!(options.smoothing >= 0.0f && options.smoothing <= 1.0f))
        return Status::error(StatusCode::invalid_argument,
                             "remesh: smoothing must be in [0, 1] (got %g)",
                             double(options.smoothing));
    if (options.surface == nullptr)
        return Status::error(StatusCode::invalid_argument,
                             "remesh: no surface function to project onto");
    std::vector<int> opp;
    SHITSUKAN_TRY(check_input(mesh, &opp));
    IsotropicRemeshStats local;
    IsotropicRemeshStats* s = stats ? stats : &local;
    *s = IsotropicRemeshStats{};
    SHITSUKAN_TRY(measure(mesh, opp, &s->before));
    // An equilateral triangle of side L has area (√3/4) L²; a mesh has about twice as many
    // triangles as vertices.
    const double expected = s->before.area / (0.4330127 * double(L) * double(L)) * 0.5;
    if (expected > double(kMaxRemeshVertices))
        return Status::error(StatusCode::too_large,
                             "remesh: about %.0f vertices expected (area %g, L %g) exceeds %d "
                             "(~%.0f bytes of work arrays)",
                             expected, s->before.area, double(L), kMaxRemeshVertices,
                             expected * 100.0);
    Remesher remesher(options, &mesh);
    SHITSUKAN_TRY(remesher.run(s));
    remesher.write(&mesh);
    SHITSUKAN_TRY(check_input(mesh, &opp));
    return measure(mesh, opp, &s->after);
}

}  // namespace shitsukan
