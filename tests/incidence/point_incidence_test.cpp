// The discretized alternative (point incidences along G) against the exact composition, and the
// row counts and conditioning of both on seed 000 Fig. 4's set-up.
#include "solvers/incidence/point_incidence.h"

#include "tests/incidence/incidence_fixtures.h"

#include <Eigen/SVD>
#include <gtest/gtest.h>

#include <iostream>

using namespace sculptline::solvers;
using namespace sculptline::solvers::incidence;
using namespace sculptline::incidence_test;

namespace {

constexpr double kRoundOff = 1e-13;
// Singular values below this fraction of the largest are round-off of zero.
constexpr double kNumericalRank = 1e-12;

// The columns of A with an entry above `floor` (the control points the curve depends on), densely.
Eigen::MatrixXd activeColumns(const SparseRows& a, double floor = 0.0)
{
    const Eigen::MatrixXd dense = Eigen::MatrixXd(a);
    std::vector<int> active;
    for (Eigen::Index j = 0; j < dense.cols(); ++j)
        if (dense.col(j).cwiseAbs().maxCoeff() > floor) active.push_back(static_cast<int>(j));
    Eigen::MatrixXd out(dense.rows(), static_cast<Eigen::Index>(active.size()));
    for (size_t k = 0; k < active.size(); ++k) out.col(static_cast<Eigen::Index>(k)) = dense.col(active[k]);
    return out;
}

}  // namespace

TEST(IncidencePoints, RowIsTheSurfacePoint)
{
    const Surface3d f = figureFourSurface();
    const SurfaceStructure s = SurfaceStructure::of(f);
    const ControlMatrix p = surfacePointRows(f);
    for (const Eigen::Vector2d& uv : {Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(0.31, 0.77), Eigen::Vector2d(1.0, 1.0)}) {
        const Eigen::SparseVector<double> row = surfacePointRow(s, uv.x(), uv.y());
        const Eigen::RowVector3d point = row.transpose() * p;
        EXPECT_LT((point.transpose() - f.evaluate(uv.x(), uv.y())).norm(), kRoundOff * 100.0);
        EXPECT_EQ(row.nonZeros(), 16);
    }
}

TEST(IncidencePoints, DiscretizedRowsSampleTheExactCurve)
{
    // Given Fig. 4's surface and diagonal domain curve, composed exactly and discretized at 271
    // uniform parameters (as many rows as the exact composition has)
    const Surface3d f = figureFourSurface();
    const Curve2d g = diagonalCurve(8);
    const SurfaceStructure s = SurfaceStructure::of(f);
    const Composition exact = compose(s, g);
    const std::vector<double> t = uniformParameters(g, static_cast<int>(exact.matrix.rows()));
    const SparseRows discrete = discretizedIncidence(s, g, t);
    // When both are applied to the unchanged surface
    const ControlMatrix sampled = discrete * surfacePointRows(f);
    const Curve3d h = applyComposition(exact, f);
    // Then they give the same surface curve: the point rows are H at the parameters ...
    double worst = 0.0;
    for (size_t k = 0; k < t.size(); ++k) worst = std::max(worst, (sampled.row(static_cast<Eigen::Index>(k)).transpose() - h.evaluate(t[k])).norm());
    EXPECT_LT(worst, 100.0 * kRoundOff);
    // ... and as matrices: discretized = E A, E the evaluation of H's space at the parameters
    const SparseRows e = evaluationMatrix(exact.space.degree, exact.space.knots, t);
    EXPECT_LT((Eigen::MatrixXd(discrete) - Eigen::MatrixXd(e * exact.matrix)).cwiseAbs().maxCoeff(), kRoundOff);
}

TEST(IncidencePoints, FigureFourRowCountsAndConditioning)
{
    // Given Fig. 4's set-up
    const Surface3d f = figureFourSurface();
    const Curve2d g = diagonalCurve(8);
    const SurfaceStructure s = SurfaceStructure::of(f);
    const Composition exact = compose(s, g);
    const Eigen::MatrixXd a = activeColumns(exact.matrix);
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(a);
    const Eigen::VectorXd& sigma = svd.singularValues();
    const auto rankOf = [](const Eigen::VectorXd& v) {
        return static_cast<int>((v.array() > kNumericalRank * v(0)).count());
    };
    const int rank = rankOf(sigma);
    std::cout << "Fig. 4, exact: " << exact.matrix.rows() << " rows, " << a.cols()
              << " of 80 control points involved, numerical rank " << rank << " (sigma > 1e-12 sigma max), sigma max "
              << sigma(0) << ", sigma_rank " << sigma(rank - 1) << ", condition on the range " << sigma(0) / sigma(rank - 1)
              << "\n  singular values:";
    for (Eigen::Index i = 0; i < sigma.size(); ++i) std::cout << " " << sigma(i);
    std::cout << "\n";
    // When discretized with as many rows, with as many rows as involved control points, and 10x more
    for (int m : {static_cast<int>(exact.matrix.rows()), static_cast<int>(a.cols()), 10 * static_cast<int>(exact.matrix.rows())}) {
        const Eigen::MatrixXd d = activeColumns(discretizedIncidence(s, g, uniformParameters(g, m)));
        const Eigen::JacobiSVD<Eigen::MatrixXd> dsvd(d);
        const Eigen::VectorXd& ds = dsvd.singularValues();
        const int drank = rankOf(ds);
        std::cout << "Fig. 4, discretized, m = " << m << ": numerical rank " << drank << ", sigma max " << ds(0)
                  << ", sigma_rank " << ds(drank - 1) << ", condition on the range " << ds(0) / ds(drank - 1) << "\n";
        // Then the discretization sees the same control points, and (its rows being combinations of
        // A's) never more rank; with at least as many rows as the exact curve has, the same rank
        EXPECT_EQ(d.cols(), a.cols());
        EXPECT_LE(drank, rank);
        if (m >= exact.matrix.rows()) {
            EXPECT_EQ(drank, rank);
        }
    }
    // And the exact system is ill-conditioned on its range (seed 000 §4.1)
    EXPECT_GT(sigma(0) / sigma(rank - 1), 1e3);
}

TEST(IncidencePoints, ExactAndDiscretizedInvolveTheSameControlPoints)
{
    // A control point is involved when its basis product is non-zero somewhere along G: the exact
    // composition and a dense sampling depend on the same ones. (A curve grazing a basis function's
    // support gives entries of any smallness in both, so they are compared above 1e-12.)
    const SurfaceStructure s = SurfaceStructure::of(figureFourSurface());
    for (const Curve2d& g : {diagonalCurve(8), curvedCurve(8), curvedCurve(9)}) {
        const Composition exact = compose(s, g);
        const SparseRows discrete = discretizedIncidence(s, g, uniformParameters(g, 4000));
        EXPECT_EQ(activeColumns(exact.matrix, 1e-12).cols(), activeColumns(discrete, 1e-12).cols());
    }
}
