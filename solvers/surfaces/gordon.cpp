#include "solvers/surfaces/gordon.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/surfaces/compatible_curves.h"
#include "solvers/surfaces/interpolation.h"
#include "solvers/surfaces/loft.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <numeric>
#include <string>

namespace sculptline::solvers::surfaces {

namespace {

using Vec3 = Eigen::Vector3d;

constexpr int kSamples = 64;          // per curve, for the intersection's initial guess
constexpr int kNewtonSteps = 40;
constexpr double kConverged = 1e-15;  // parameter step below round-off of [0, 1]
constexpr double kSameParameter = 1e-12;  // intersection parameters this close need no split
constexpr double kDefaultMeetRelative = 1e-4;

struct Hit {
    double a = 0.0, b = 0.0, gap = 0.0;
};

std::vector<Vec3> samplesOf(const Curve3d& c)
{
    std::vector<Vec3> s;
    for (int i = 0; i <= kSamples; ++i) s.push_back(c.evaluate(static_cast<double>(i) / kSamples));
    return s;
}

// Closest points of two curves on [0, 1]: the closest pair of samples, then Gauss-Newton on
// C(a) - D(b) = 0.
Hit intersect(const Curve3d& c, const std::vector<Vec3>& cs, const Curve3d& d, const std::vector<Vec3>& ds)
{
    Hit h;
    h.gap = 1e300;
    for (int i = 0; i <= kSamples; ++i)
        for (int j = 0; j <= kSamples; ++j) {
            const double g = (cs[i] - ds[j]).squaredNorm();
            if (g < h.gap) h = {double(i) / kSamples, double(j) / kSamples, g};
        }
    for (int it = 0; it < kNewtonSteps; ++it) {
        const auto dc = c.derivatives(h.a, 1);
        const auto dd = d.derivatives(h.b, 1);
        const Vec3 f = dc[0] - dd[0];
        Eigen::Matrix<double, 3, 2> J;
        J << dc[1], -dd[1];
        const Eigen::Vector2d step = (J.transpose() * J).ldlt().solve(-J.transpose() * f);
        if (!step.allFinite()) break;
        h.a = std::clamp(h.a + step(0), 0.0, 1.0);
        h.b = std::clamp(h.b + step(1), 0.0, 1.0);
        if (step.norm() < kConverged) break;
    }
    h.gap = (c.evaluate(h.a) - d.evaluate(h.b)).norm();
    return h;
}

// The curve between params[0] and params.back(), each piece [params[l], params[l+1]] mapped
// affinely onto [targets[l], targets[l+1]] and joined with C0 knots (shape unchanged).
Curve3d reparameterize(const Curve3d& c, const std::vector<double>& params, const std::vector<double>& targets)
{
    bool same = true;
    for (size_t l = 0; l < params.size(); ++l) same = same && std::abs(params[l] - targets[l]) <= kSameParameter;
    if (same) return c;
    const int p = c.degree();
    KnotVector knots(p + 1, 0.0);
    std::vector<Vec3> pts;
    for (size_t l = 0; l + 1 < params.size(); ++l) {
        const Curve3d piece = c.extract(params[l], params[l + 1]);
        const double s = (targets[l + 1] - targets[l]) / (piece.domainEnd() - piece.domainStart());
        for (size_t k = p + 1; k + p + 1 < piece.knots().size(); ++k)
            knots.push_back(targets[l] + (piece.knots()[k] - piece.domainStart()) * s);
        if (l + 2 < params.size()) knots.insert(knots.end(), p, targets[l + 1]);
        pts.insert(pts.end(), piece.points().begin() + (l == 0 ? 0 : 1), piece.points().end());
    }
    knots.insert(knots.end(), p + 1, 1.0);
    return Curve3d(p, std::move(knots), std::move(pts));
}

// A surface elevated and refined in direction d to the layout (degree, knots).
Surface3d conform(Surface3d s, Direction d, const CurveLayout& layout)
{
    if (s.degree(d) < layout.degree) s = s.elevate(d, layout.degree - s.degree(d));
    std::vector<double> missing;
    const KnotVector& have = s.knots(d);
    size_t b = 0;
    for (double k : layout.knots) {
        if (b < have.size() && have[b] == k) ++b;
        else missing.push_back(k);
    }
    return missing.empty() ? s : s.refine(d, missing);
}

CurveLayout mergedLayout(int degreeA, const KnotVector& a, int degreeB, const KnotVector& b)
{
    const auto dummy = [](int p, const KnotVector& k) {
        return Curve3d(p, k, std::vector<Vec3>(k.size() - p - 1, Vec3::Zero()));
    };
    return commonLayout({dummy(degreeA, a), dummy(degreeB, b)});
}

}  // namespace

GordonResult gordon(const std::vector<Curve3d>& uIn, const std::vector<Curve3d>& vIn, const GordonOptions& options)
{
    if (uIn.size() < 2 || vIn.size() < 2)
        throw GeometryError("curves: a Gordon surface needs at least two curves in each direction");
    std::vector<Curve3d> cu, cv;
    Eigen::AlignedBox3d box;
    for (const auto* family : {&uIn, &vIn})
        for (const Curve3d& c : *family) {
            if (c.isRational()) throw GeometryError("curves: rational curves are not supported by the Gordon surface");
            for (const Vec3& p : c.points()) box.extend(p);
            (family == &uIn ? cu : cv).push_back(normalizedCurve(c));
        }
    const double meet = options.meetTolerance > 0.0 ? options.meetTolerance : kDefaultMeetRelative * box.diagonal().norm();
    const size_t K = cu.size(), L = cv.size();
    std::vector<std::vector<Hit>> hit(K, std::vector<Hit>(L));
    GordonResult result{Surface3d(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, 2, 2, std::vector<Vec3>(4, Vec3::Zero())), {}, {}, 0.0};
    std::vector<std::vector<Vec3>> su, sv;
    for (const Curve3d& c : cu) su.push_back(samplesOf(c));
    for (const Curve3d& c : cv) sv.push_back(samplesOf(c));
    for (size_t k = 0; k < K; ++k)
        for (size_t l = 0; l < L; ++l) {
            hit[k][l] = intersect(cu[k], su[k], cv[l], sv[l]);
            if (!(hit[k][l].gap <= meet))
                throw GeometryError("curves: u-curve " + std::to_string(k) + " and v-curve " + std::to_string(l) +
                                    " do not intersect (closest " + std::to_string(hit[k][l].gap) + ", tolerance " +
                                    std::to_string(meet) + ")");
            result.maxGap = std::max(result.maxGap, hit[k][l].gap);
        }
    // Order each family along the other (by the parameter of its hit on the other family's first
    // curve), then orient each curve so that its hits increase.
    std::vector<size_t> ou(K), ov(L);
    std::iota(ou.begin(), ou.end(), 0);
    std::iota(ov.begin(), ov.end(), 0);
    std::sort(ov.begin(), ov.end(), [&](size_t x, size_t y) { return hit[0][x].a < hit[0][y].a; });
    std::sort(ou.begin(), ou.end(), [&](size_t x, size_t y) { return hit[x][0].b < hit[y][0].b; });
    std::vector<std::vector<double>> a(K, std::vector<double>(L)), b(L, std::vector<double>(K));
    for (size_t k = 0; k < K; ++k)
        for (size_t l = 0; l < L; ++l) {
            a[k][l] = hit[ou[k]][ov[l]].a;
            b[l][k] = hit[ou[k]][ov[l]].b;
        }
    std::vector<Curve3d> C, D;
    for (size_t k = 0; k < K; ++k) C.push_back(cu[ou[k]]);
    for (size_t l = 0; l < L; ++l) D.push_back(cv[ov[l]]);
    const auto orient = [](std::vector<Curve3d>& curves, std::vector<std::vector<double>>& params) {
        for (size_t k = 0; k < curves.size(); ++k) {
            if (params[k].front() < params[k].back()) continue;
            curves[k] = reversedCurve(curves[k]);
            for (double& t : params[k]) t = 1.0 - t;
        }
        for (size_t k = 0; k < curves.size(); ++k)
            for (size_t l = 1; l < params[k].size(); ++l)
                if (!(params[k][l] > params[k][l - 1]))
                    throw GeometryError("curves: the network is not grid-like (a curve meets the other family out of order)");
    };
    orient(C, a);
    orient(D, b);
    // Common parameters: means of the hits, ends 0 and 1 (curves are trimmed to the outer curves).
    std::vector<double> u(L), v(K);
    for (size_t l = 0; l < L; ++l) {
        u[l] = 0.0;
        for (size_t k = 0; k < K; ++k) u[l] += a[k][l] / K;
    }
    for (size_t k = 0; k < K; ++k) {
        v[k] = 0.0;
        for (size_t l = 0; l < L; ++l) v[k] += b[l][k] / L;
    }
    u.front() = v.front() = 0.0;
    u.back() = v.back() = 1.0;
    for (size_t k = 0; k < K; ++k) C[k] = reparameterize(C[k], a[k], u);
    for (size_t l = 0; l < L; ++l) D[l] = reparameterize(D[l], b[l], v);

    const int qu = std::min<int>(3, static_cast<int>(L) - 1);
    const int qv = std::min<int>(3, static_cast<int>(K) - 1);
    const CurveInterpolator iu(u, qu), iv(v, qv);
    // L1: skin of the u-curves across v at v_k; L2: skin of the v-curves across u, transposed.
    const std::vector<Curve3d> cc = makeCompatible(C), dc = makeCompatible(D);
    const auto skin = [](const std::vector<Curve3d>& sections, const CurveInterpolator& across) {
        const int n = sections.front().pointCount();
        ControlMatrix data(static_cast<Eigen::Index>(sections.size()), n * 3);
        for (size_t k = 0; k < sections.size(); ++k)
            for (int i = 0; i < n; ++i) data.block(k, i * 3, 1, 3) = sections[k].points()[i].transpose();
        return Surface3d::fromGroupedRows(Direction::V, sections.front().degree(), across.degree(),
                                          sections.front().knots(), across.knots(), across.solve(data), false);
    };
    Surface3d l1 = skin(cc, iv);
    Surface3d l2 = transposed(skin(dc, iu));
    // T: tensor interpolation of the grid Q_kl = C_k(u_l): across u, then across v.
    ControlMatrix grid(static_cast<Eigen::Index>(L), static_cast<Eigen::Index>(K) * 3);
    for (size_t l = 0; l < L; ++l)
        for (size_t k = 0; k < K; ++k) grid.block(l, k * 3, 1, 3) = C[k].evaluate(u[l]).transpose();
    const ControlMatrix rowsU = iu.solve(grid);  // row i: control row i in u, points over k
    ControlMatrix byV(static_cast<Eigen::Index>(K), rowsU.rows() * 3);
    for (Eigen::Index i = 0; i < rowsU.rows(); ++i)
        for (size_t k = 0; k < K; ++k) byV.block(k, i * 3, 1, 3) = rowsU.block(i, k * 3, 1, 3);
    Surface3d t = Surface3d::fromGroupedRows(Direction::V, qu, qv, iu.knots(), iv.knots(), iv.solve(byV), false);

    const CurveLayout lu = mergedLayout(l1.degreeU(), l1.knotsU(), qu, iu.knots());
    const CurveLayout lv = mergedLayout(l2.degreeV(), l2.knotsV(), qv, iv.knots());
    for (Surface3d* s : {&l1, &l2, &t}) *s = conform(conform(*s, Direction::U, lu), Direction::V, lv);
    std::vector<Vec3> pts(l1.points().size());
    for (size_t i = 0; i < pts.size(); ++i) pts[i] = l1.points()[i] + l2.points()[i] - t.points()[i];
    result.surface = Surface3d(lu.degree, lv.degree, lu.knots, lv.knots, l1.countU(), l1.countV(), std::move(pts));
    result.uParams = u;
    result.vParams = v;
    return result;
}

}  // namespace sculptline::solvers::surfaces
