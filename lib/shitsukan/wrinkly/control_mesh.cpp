#include "shitsukan/wrinkly/control_mesh.hpp"

#include "shitsukan/core/scalar.hpp"
#include "shitsukan/geom/basis.hpp"

namespace shitsukan {

WrControlMesh make_control_mesh(int cols, int rows) {
    WrControlMesh m;
    m.cols = cols > 0 ? cols : 0;
    m.rows = rows > 0 ? rows : 0;
    if ((long long)m.cols * m.rows <= kMaxWrControlPoints)
        m.points.resize(std::size_t(m.cols) * std::size_t(m.rows));
    return m;
}

Status validate_control_mesh(const WrControlMesh& mesh, SurfaceBasis basis, int degree) {
    if (degree < 1 || degree > kMaxBasisDegree)
        return Status::error(StatusCode::invalid_argument, "degree n must be in 1..%d (got %d)",
                             kMaxBasisDegree, degree);
    if ((long long)mesh.cols * mesh.rows > kMaxWrControlPoints)
        return Status::error(
            StatusCode::too_large,
            "control mesh of %d x %d points is larger than the limit of %ld points", mesh.cols,
            mesh.rows, kMaxWrControlPoints);
    if (mesh.cols < 1 || mesh.rows < 1 ||
        mesh.points.size() != std::size_t(mesh.cols) * std::size_t(mesh.rows))
        return Status::error(StatusCode::invalid_argument,
                             "control mesh is not a square grid: %d x %d but %zu points", mesh.cols,
                             mesh.rows, mesh.points.size());
    if (basis == SurfaceBasis::bezier && (mesh.cols != degree + 1 || mesh.rows != degree + 1))
        return Status::error(
            StatusCode::invalid_argument,
            "a degree-%d Bezier WR mesh needs %d x %d control points (got %d x %d)", degree,
            degree + 1, degree + 1, mesh.cols, mesh.rows);
    if (basis == SurfaceBasis::bspline && (mesh.cols < degree + 1 || mesh.rows < degree + 1))
        return Status::error(StatusCode::invalid_argument,
                             "a degree-%d B-spline WR mesh needs at least %d x %d control points "
                             "(got %d x %d)",
                             degree, degree + 1, degree + 1, mesh.cols, mesh.rows);
    for (int r = 0; r < mesh.rows; ++r) {
        for (int c = 0; c < mesh.cols; ++c) {
            const WrControlPoint& p = mesh.at(c, r);
            if (!is_finite(p.position) || !is_finite(p.height) || !is_finite(p.color) ||
                !is_finite(p.direction))
                return Status::error(StatusCode::invalid_argument,
                                     "control point (%d, %d) has a non-finite position, height, "
                                     "colour or direction",
                                     c, r);
            const float big[7] = {p.position.x, p.position.y,  p.position.z, p.height,
                                  p.direction.x, p.direction.y, p.direction.z};
            for (float v : big)
                if (!(v >= -kMaxWrCoordinate && v <= kMaxWrCoordinate))
                    return Status::error(StatusCode::invalid_argument,
                                         "control point (%d, %d): position, height and direction "
                                         "must be within +-%g (got %g)",
                                         c, r, double(kMaxWrCoordinate), double(v));
            if (!(p.transparency >= 0.0f && p.transparency <= 1.0f))
                return Status::error(
                    StatusCode::invalid_argument,
                    "control point (%d, %d): transparency must be in [0, 1] (got %g)", c, r,
                    double(p.transparency));
            if (!(p.delta > 0.0f && p.delta < 1.0f))
                return Status::error(StatusCode::invalid_argument,
                                     "control point (%d, %d): delta must be in (0, 1) (got %g; "
                                     "eq. 17 needs 0 < delta < 1)",
                                     c, r, double(p.delta));
        }
    }
    return Status::success();
}

}  // namespace shitsukan
