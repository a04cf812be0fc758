// bench_branch_mesh — the hirota1998 §5 branch mesh (docs/papers/hirota1998.md §6): marching
// tetrahedra at L0/2 = 0.165 cm, then isotropic remeshing to L0 = 0.33 cm, 8 passes.
//   - marching tetrahedra: time per mesh, and the share of it spent sampling f on the grid
//     (the same grid sampled alone, timed in the same run): the polygonisation's overhead;
//   - the remesher against CGAL's Polygon_mesh_processing::isotropic_remeshing (the same
//     Botsch-Kobbelt loop) on the same input mesh, target length and number of passes, with a
//     projection functor doing the same 3 Newton steps onto f = 0 (boundary vertices keep
//     their z, relax_constraints lets them slide along the rims as ours do). Triangles per
//     second counts the input triangles processed per second of a whole remesh.
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "bench.hpp"
#include "shitsukan/bark/branch_shape.hpp"
#include "shitsukan/geom/isotropic_remesh.hpp"
#include "shitsukan/geom/marching_tetrahedra.hpp"

using namespace shitsukan;

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using CgalMesh = CGAL::Surface_mesh<Point>;

const BranchShapeParams kShape;

float shape_f(Vec3 p, const void*) { return branch_shape_value(kShape, p); }

// The same projection as the remesher's step 5: 3 Newton steps with the central-difference
// gradient (step L/20); boundary vertices use the gradient without its z component.
Vec3 project(Vec3 p, bool boundary, float L) {
    for (int s = 0; s < 3; ++s) {
        Vec3 g = implicit_gradient(&shape_f, nullptr, p, 0.05f * L);
        if (boundary) g.z = 0.0f;
        float gg = dot(g, g);
        if (!(gg > 1e-12f)) break;
        p -= g * (shape_f(p, nullptr) / gg);
    }
    return p;
}

struct CgalProjection {
    const CgalMesh* mesh;
    float L;
    Point operator()(CgalMesh::Vertex_index v) const {
        const Point& q = mesh->point(v);
        Vec3 p = project(Vec3{float(q.x()), float(q.y()), float(q.z())}, mesh->is_border(v), L);
        return Point(p.x, p.y, p.z);
    }
};

void to_cgal(const TriangleMesh& m, CgalMesh* out) {
    out->clear();
    std::vector<CgalMesh::Vertex_index> vs;
    for (Vec3 p : m.positions) vs.push_back(out->add_vertex(Point(p.x, p.y, p.z)));
    for (int t = 0; t < m.triangle_count(); ++t)
        out->add_face(vs[m.indices[3 * t]], vs[m.indices[3 * t + 1]], vs[m.indices[3 * t + 2]]);
}

std::string format(const char* f, double a, double b = 0) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, a, b);
    return buf;
}

}  // namespace

SHITSUKAN_BENCH(branch_mesh_vs_cgal) {
    // --quick (CI): the quick figure's L0 = 0.6 cm; CGAL alone takes ~0.8 s per full remesh.
    const bool quick = bench::g_min_seconds < 0.1;
    const float L0 = quick ? 0.6f : 0.33f;
    MarchingTetrahedraOptions mt;
    mt.spacing = 0.5f * L0;
    branch_shape_box(kShape, mt.spacing, &mt.box_min, &mt.box_max);
    mt.cut_z_min = mt.cut_z_max = true;
    mt.compute_normals = false;
    TriangleMesh input;
    MarchingTetrahedraStats ms;
    if (Status s = marching_tetrahedra(&shape_f, nullptr, mt, input, &ms); !s) {
        bench::info("branch mesh", std::string("set-up failed: ") + s.message());
        return;
    }
    // The whole march against the grid alone (the same nodes sampled in the same order), in
    // turns; medians.
    const Vec3 c = ms.cell;
    const bench::Pair march_t = bench::in_turns(
        [&] {
            TriangleMesh m;
            Status s = marching_tetrahedra(&shape_f, nullptr, mt, m);
            bench::sink(s.ok() ? m.triangle_count() : -1);
        },
        [&] {
            float acc = 0;
            for (int k = 0; k <= ms.nz; ++k)
                for (int j = 0; j <= ms.ny; ++j)
                    for (int i = 0; i <= ms.nx; ++i)
                        acc += shape_f({mt.box_min.x + float(i) * c.x,
                                        mt.box_min.y + float(j) * c.y,
                                        mt.box_min.z + float(k) * c.z},
                                       nullptr);
            bench::sink(acc);
        });
    const double march = march_t.ours.median, sample = march_t.peer.median;
    const long long nodes = (long long)(ms.nx + 1) * (ms.ny + 1) * (ms.nz + 1);
    bench::info(format("marching tetrahedra, branch shape h = %.3f cm", double(mt.spacing)),
                std::to_string(nodes) + " nodes -> " + std::to_string(input.triangle_count()) +
                    " triangles in " +
                    format("%.2f ms (%.0f %% of it sampling f on the grid)", march * 1e-6,
                           100.0 * sample / march));

    IsotropicRemeshOptions ro;
    ro.target_edge_length = L0;
    ro.surface = &shape_f;
    IsotropicRemeshStats rs;
    TriangleMesh out;
    CgalMesh cg;
    const bench::Pair t = bench::in_turns(
        [&] {
            out = input;
            Status s = isotropic_remesh(ro, out, &rs);
            bench::sink(s.ok() ? out.triangle_count() : -1);
        },
        [&] {
            to_cgal(input, &cg);
            CGAL::Polygon_mesh_processing::isotropic_remeshing(
                faces(cg), double(L0), cg,
                CGAL::parameters::number_of_iterations(8)
                    .relax_constraints(true)
                    .projection_functor(CgalProjection{&cg, L0}));
            bench::sink(cg.number_of_faces());
        });
    bench::report("isotropic remesh of the branch (" + std::to_string(input.triangle_count()) +
                      " -> ~" + std::to_string(out.triangle_count()) + " triangles, 8 passes)",
                  t, "CGAL isotropic_remeshing");
    // CGAL's result measured with the same yardstick.
    TriangleMesh back;
    {
        std::vector<std::uint32_t> id(cg.number_of_vertices() + cg.number_of_removed_vertices());
        for (CgalMesh::Vertex_index v : cg.vertices()) {
            const Point& q = cg.point(v);
            id[std::size_t(v)] = back.add_vertex(Vec3{float(q.x()), float(q.y()), float(q.z())});
        }
        for (CgalMesh::Face_index f : cg.faces()) {
            std::uint32_t c[3];
            int k = 0;
            for (CgalMesh::Vertex_index v : cg.vertices_around_face(cg.halfedge(f)))
                if (k < 3) c[k++] = id[std::size_t(v)];
            back.add_triangle(c[0], c[1], c[2]);
        }
    }
    MeshQuality cq;
    Status cs = mesh_quality(back, cq);
    const double tri = double(input.triangle_count()), ours = t.ours.median, peer = t.peer.median;
    bench::info("remesher triangles per second",
                "shitsukan " + std::to_string(long(tri / (ours * 1e-9))) + ", CGAL " +
                    std::to_string(long(tri / (peer * 1e-9))) + " (input triangles / s); ours " +
                    std::to_string(out.triangle_count()) + " triangles, edge CV " +
                    format("%.3f, %.2f %% of triangles above 25 deg", rs.after.edge_length_cv,
                           100.0 * rs.after.fraction_angle_above_25) +
                    "; CGAL " + std::to_string(cg.number_of_faces()) + " triangles, " +
                    (cs ? format("edge CV %.3f, %.2f %% above 25 deg", cq.edge_length_cv,
                                 100.0 * cq.fraction_angle_above_25)
                        : std::string("not measurable: ") + cs.message()));
}
