#include "solvers/incidence/incidence_system.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/incidence/point_incidence.h"

namespace sculptline::solvers::incidence {

std::vector<int> IncidenceSystem::hardRows() const
{
    std::vector<int> rows;
    for (size_t i = 0; i < hard.size(); ++i)
        if (hard[i]) rows.push_back(static_cast<int>(i));
    return rows;
}

std::vector<int> IncidenceSystem::softRows() const
{
    std::vector<int> rows;
    for (size_t i = 0; i < hard.size(); ++i)
        if (!hard[i]) rows.push_back(static_cast<int>(i));
    return rows;
}

IncidenceSystem stackIncidences(const SurfaceStructure& surface, const std::vector<CurveRequest>& curves,
                                const StackOptions& options)
{
    IncidenceSystem system;
    std::vector<Eigen::Triplet<double>> triplets;
    std::vector<ControlMatrix> rhsBlocks;
    int rows = 0;
    for (size_t c = 0; c < curves.size(); ++c) {
        const CurveRequest& curve = curves[c];
        if (curve.request.isRational()) throw GeometryError("request curve: must be non-rational");
        const Curve3d request = curve.request.isClosed() ? curve.request.clamped() : curve.request;
        Composition composition = compose(surface, curve.domain, interiorBreakpoints(request.degree(), request.knots()));
        if (options.reduceMultiplicities) composition = reduceMultiplicities(composition, surface, curve.domain);
        const SparseRows compatibility = compatibilityMatrix(request.degree(), request.knots(), composition.space);
        ControlMatrix points(request.pointCount(), 3);
        for (int i = 0; i < request.pointCount(); ++i) points.row(i) = request.points()[i].transpose();
        rhsBlocks.push_back(compatibility * points);
        for (int k = 0; k < composition.matrix.outerSize(); ++k)
            for (SparseRows::InnerIterator it(composition.matrix, k); it; ++it)
                triplets.emplace_back(rows + k, static_cast<int>(it.col()), it.value());
        const int count = static_cast<int>(composition.matrix.rows());
        system.blocks.push_back({RowBlock::Kind::Curve, rows, count, static_cast<int>(c)});
        system.hard.insert(system.hard.end(), static_cast<size_t>(count), curve.fixed);
        system.compositions.push_back(std::move(composition));
        rows += count;
    }
    if (options.crossingRows) {
        for (size_t a = 0; a < curves.size(); ++a) {
            for (size_t b = a + 1; b < curves.size(); ++b) {
                for (const Crossing& x : curveCrossings(curves[a].domain, curves[b].domain)) {
                    const Eigen::Vector3d pa = curves[a].request.evaluate(x.t1);
                    const Eigen::Vector3d pb = curves[b].request.evaluate(x.t2);
                    const Eigen::Vector3d target = curves[a].fixed ? pa : (curves[b].fixed ? pb : Eigen::Vector3d(0.5 * (pa + pb)));
                    const Eigen::SparseVector<double> row = surfacePointRow(surface, x.point.x(), x.point.y());
                    for (Eigen::SparseVector<double>::InnerIterator it(row); it; ++it)
                        triplets.emplace_back(rows, static_cast<int>(it.index()), it.value());
                    rhsBlocks.push_back(target.transpose());
                    RowBlock block{RowBlock::Kind::Crossing, rows, 1, static_cast<int>(a), static_cast<int>(b), x.t1, x.t2,
                                   (pa - pb).norm()};
                    system.blocks.push_back(block);
                    system.hard.push_back(curves[a].fixed || curves[b].fixed);
                    ++rows;
                }
            }
        }
    }
    system.matrix.resize(rows, surface.columnCount());
    system.matrix.setFromTriplets(triplets.begin(), triplets.end());
    system.rhs.resize(rows, 3);
    int at = 0;
    for (const ControlMatrix& block : rhsBlocks) {
        system.rhs.middleRows(at, block.rows()) = block;
        at += static_cast<int>(block.rows());
    }
    return system;
}

}  // namespace sculptline::solvers::incidence
