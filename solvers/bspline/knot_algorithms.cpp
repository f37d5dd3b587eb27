#include "solvers/bspline/knot_algorithms.h"

#include "solvers/bspline/geometry_error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace sculptline::solvers {
namespace {

// Largest Euclidean distance over groups of `groupSize` columns (see removeKnot).
double groupDistance(const Eigen::RowVectorXd& a, const Eigen::RowVectorXd& b, int groupSize)
{
    double worst = 0.0;
    for (int c = 0; c < a.size(); c += groupSize) {
        const int len = std::min<int>(groupSize, static_cast<int>(a.size()) - c);
        worst = std::max(worst, (a.segment(c, len) - b.segment(c, len)).norm());
    }
    return worst;
}

void checkInsideDomain(int degree, const KnotVector& knots, double u, const char* what)
{
    const double a = knots[degree];
    const double b = knots[knots.size() - degree - 1];
    if (!std::isfinite(u) || !(u > a && u < b)) {
        std::ostringstream msg;
        msg << what << ": " << u << " is not strictly inside the parameter domain [" << a << ", " << b << "]";
        throw GeometryError(msg.str());
    }
}

// Boehm insertion (The NURBS Book, A5.1) without the public preconditions: u may also be a domain
// end of an unclamped knot vector, as long as U[0] < u < U[m]. k is the last index with U[k] <= u.
KnotsAndPoints insertKnotUnchecked(int p, const KnotVector& U, const ControlMatrix& P, double u, int r)
{
    const int s = knotMultiplicity(U, u);
    const int np = static_cast<int>(P.rows()) - 1;
    const int k = static_cast<int>(std::upper_bound(U.begin(), U.end(), u) - U.begin()) - 1;
    const int mp = np + p + 1;
    KnotsAndPoints out;
    out.knots.resize(U.size() + r);
    for (int i = 0; i <= k; ++i) out.knots[i] = U[i];
    for (int i = 1; i <= r; ++i) out.knots[k + i] = u;
    for (int i = k + 1; i <= mp; ++i) out.knots[i + r] = U[i];

    ControlMatrix& Q = out.points;
    Q.resize(P.rows() + r, P.cols());
    for (int i = 0; i <= k - p; ++i) Q.row(i) = P.row(i);
    for (int i = k - s; i <= np; ++i) Q.row(i + r) = P.row(i);
    ControlMatrix R = P.middleRows(k - p, p - s + 1);
    int L = 0;
    for (int j = 1; j <= r; ++j) {
        L = k - p + j;
        for (int i = 0; i <= p - j - s; ++i) {
            const double alpha = (u - U[L + i]) / (U[i + k + 1] - U[L + i]);
            R.row(i) = alpha * R.row(i + 1) + (1.0 - alpha) * R.row(i);
        }
        Q.row(L) = R.row(0);
        Q.row(k + r - j - s) = R.row(p - j - s);
    }
    for (int i = L + 1; i < k - s; ++i) Q.row(i) = R.row(i - L);
    return out;
}

}  // namespace

KnotsAndPoints insertKnot(int p, const KnotVector& U, const ControlMatrix& P, double u, int r)
{
    checkInsideDomain(p, U, u, "knot");
    if (r < 0) throw GeometryError("times: must be non-negative, got " + std::to_string(r));
    const int s = knotMultiplicity(U, u);
    if (s + r > p) {
        std::ostringstream msg;
        msg << "times: knot " << u << " has multiplicity " << s << "; inserting it " << r << " more times exceeds the degree "
            << p;
        throw GeometryError(msg.str());
    }
    if (r == 0) return {U, P};
    return insertKnotUnchecked(p, U, P, u, r);
}

KnotsAndPoints refineKnots(int p, const KnotVector& U, const ControlMatrix& P, const std::vector<double>& X)
{
    if (X.empty()) return {U, P};
    for (size_t j = 0; j < X.size(); ++j) {
        checkInsideDomain(p, U, X[j], "knots to insert");
        if (j > 0 && X[j] < X[j - 1]) throw GeometryError("knots to insert: must be sorted in non-decreasing order");
    }
    for (size_t j = 0; j < X.size();) {
        size_t e = j;
        while (e < X.size() && X[e] == X[j]) ++e;
        if (knotMultiplicity(U, X[j]) + static_cast<int>(e - j) > p) {
            std::ostringstream msg;
            msg << "knots to insert: knot " << X[j] << " would exceed multiplicity " << p;
            throw GeometryError(msg.str());
        }
        j = e;
    }
    // The NURBS Book, A5.4.
    const int n = static_cast<int>(P.rows()) - 1;
    const int m = n + p + 1;
    const int r = static_cast<int>(X.size()) - 1;
    const int a = findSpan(p, U, X[0]);
    const int b = findSpan(p, U, X[r]) + 1;
    KnotsAndPoints out;
    KnotVector& Ub = out.knots;
    ControlMatrix& Q = out.points;
    Ub.assign(U.size() + X.size(), 0.0);
    Q.resize(P.rows() + static_cast<int>(X.size()), P.cols());
    for (int j = 0; j <= a - p; ++j) Q.row(j) = P.row(j);
    for (int j = b - 1; j <= n; ++j) Q.row(j + r + 1) = P.row(j);
    for (int j = 0; j <= a; ++j) Ub[j] = U[j];
    for (int j = b + p; j <= m; ++j) Ub[j + r + 1] = U[j];
    int i = b + p - 1;
    int k = b + p + r;
    for (int j = r; j >= 0; --j) {
        while (X[j] <= U[i] && i > a) {
            Q.row(k - p - 1) = P.row(i - p - 1);
            Ub[k] = U[i];
            --k;
            --i;
        }
        Q.row(k - p - 1) = Q.row(k - p);
        for (int l = 1; l <= p; ++l) {
            const int ind = k - p + l;
            double alpha = Ub[k + l] - X[j];
            if (std::abs(alpha) == 0.0) {
                Q.row(ind - 1) = Q.row(ind);
            } else {
                alpha /= (Ub[k + l] - U[i - p + l]);
                Q.row(ind - 1) = alpha * Q.row(ind - 1) + (1.0 - alpha) * Q.row(ind);
            }
        }
        Ub[k] = X[j];
        --k;
    }
    return out;
}

KnotsAndPoints clampEnds(int p, const KnotVector& U, const ControlMatrix& P)
{
    const int n = static_cast<int>(P.rows()) - 1;
    const double a = U[p];
    const double b = U[n + 1];
    KnotsAndPoints cur{U, P};
    // Raise the multiplicity of each domain end to p: the curve then passes through one control
    // point there, and the points outside [a, b] can be dropped.
    const int sa = knotMultiplicity(U, a);
    if (sa < p) cur = insertKnotUnchecked(p, cur.knots, cur.points, a, p - sa);
    const int sb = knotMultiplicity(cur.knots, b);
    if (sb < p) cur = insertKnotUnchecked(p, cur.knots, cur.points, b, p - sb);
    const KnotVector& K = cur.knots;
    const int lastA = static_cast<int>(std::upper_bound(K.begin(), K.end(), a) - K.begin()) - 1;
    const int firstB = static_cast<int>(std::lower_bound(K.begin(), K.end(), b) - K.begin());
    KnotsAndPoints out;
    out.knots.assign(p + 1, a);
    out.knots.insert(out.knots.end(), K.begin() + lastA + 1, K.begin() + firstB);
    out.knots.insert(out.knots.end(), p + 1, b);
    const int count = static_cast<int>(out.knots.size()) - p - 1;
    // N_{lastA-p} is the basis function equal to 1 at u = a.
    out.points = cur.points.middleRows(lastA - p, count);
    return out;
}

KnotsAndPoints extractSegment(int p, const KnotVector& U, const ControlMatrix& P, double u0, double u1)
{
    KnotsAndPoints cur = clampEnds(p, U, P);
    auto raise = [&](double u) {
        const double a = cur.knots[p];
        const double b = cur.knots[cur.knots.size() - p - 1];
        if (u > a && u < b) {
            const int s = knotMultiplicity(cur.knots, u);
            if (s < p) cur = insertKnotUnchecked(p, cur.knots, cur.points, u, p - s);
        }
    };
    raise(u0);
    raise(u1);
    const KnotVector& K = cur.knots;
    const int last0 = static_cast<int>(std::upper_bound(K.begin(), K.end(), u0) - K.begin()) - 1;
    const int first1 = static_cast<int>(std::lower_bound(K.begin(), K.end(), u1) - K.begin());
    KnotsAndPoints out;
    out.knots.assign(p + 1, u0);
    out.knots.insert(out.knots.end(), K.begin() + last0 + 1, K.begin() + first1);
    out.knots.insert(out.knots.end(), p + 1, u1);
    const int count = static_cast<int>(out.knots.size()) - p - 1;
    out.points = cur.points.middleRows(last0 - p, count);
    return out;
}

KnotsAndPoints elevateDegree(int p, const KnotVector& Uin, const ControlMatrix& Pin, int t)
{
    if (t < 0) throw GeometryError("times: must be non-negative, got " + std::to_string(t));
    if (p + t > kMaxDegree) {
        throw GeometryError("times: elevating degree " + std::to_string(p) + " by " + std::to_string(t) +
                            " exceeds the supported maximum " + std::to_string(kMaxDegree));
    }
    if (t == 0) return {Uin, Pin};
    // A5.9 assumes clamped ends; an unclamped (e.g. periodic-window) curve is clamped first.
    KnotsAndPoints clamped = clampEnds(p, Uin, Pin);
    const KnotVector& U = clamped.knots;
    const ControlMatrix& P = clamped.points;

    // The NURBS Book, A5.9.
    const int n = static_cast<int>(P.rows()) - 1;
    const int dim = static_cast<int>(P.cols());
    const int m = n + p + 1;
    const int ph = p + t;
    const int ph2 = ph / 2;
    Eigen::MatrixXd bezalfs = Eigen::MatrixXd::Zero(ph + 1, p + 1);
    bezalfs(0, 0) = bezalfs(ph, p) = 1.0;
    for (int i = 1; i <= ph2; ++i) {
        const double inv = 1.0 / binomial(ph, i);
        const int mpi = std::min(p, i);
        for (int j = std::max(0, i - t); j <= mpi; ++j) bezalfs(i, j) = inv * binomial(p, j) * binomial(t, i - j);
    }
    for (int i = ph2 + 1; i <= ph - 1; ++i) {
        const int mpi = std::min(p, i);
        for (int j = std::max(0, i - t); j <= mpi; ++j) bezalfs(i, j) = bezalfs(ph - i, p - j);
    }
    // Upper bound on the size of the result: every distinct knot gains t multiplicity.
    int distinct = 0;
    for (int i = 0; i <= m; ++i)
        if (i == 0 || U[i] != U[i - 1]) ++distinct;
    ControlMatrix Q(P.rows() + static_cast<Eigen::Index>(distinct) * t, dim);
    KnotVector Uh(U.size() + static_cast<size_t>(distinct) * t, 0.0);
    ControlMatrix bpts(p + 1, dim), ebpts(ph + 1, dim), nextbpts(std::max(p - 1, 1), dim);
    std::vector<double> alfs(std::max(p - 1, 1));

    int mh = ph, kind = ph + 1, r = -1, a = p, b = p + 1, cind = 1;
    double ua = U[0];
    Q.row(0) = P.row(0);
    for (int i = 0; i <= ph; ++i) Uh[i] = ua;
    for (int i = 0; i <= p; ++i) bpts.row(i) = P.row(i);
    while (b < m) {
        int i = b;
        while (b < m && U[b] == U[b + 1]) ++b;
        const int mul = b - i + 1;
        mh += mul + t;
        const double ub = U[b];
        const int oldr = r;
        r = p - mul;
        const int lbz = oldr > 0 ? (oldr + 2) / 2 : 1;
        const int rbz = r > 0 ? ph - (r + 1) / 2 : ph;
        if (r > 0) {
            const double numer = ub - ua;
            for (int k = p; k > mul; --k) alfs[k - mul - 1] = numer / (U[a + k] - ua);
            for (int j = 1; j <= r; ++j) {
                const int save = r - j;
                const int s = mul + j;
                for (int k = p; k >= s; --k) bpts.row(k) = alfs[k - s] * bpts.row(k) + (1.0 - alfs[k - s]) * bpts.row(k - 1);
                nextbpts.row(save) = bpts.row(p);
            }
        }
        for (i = lbz; i <= ph; ++i) {
            ebpts.row(i).setZero();
            const int mpi = std::min(p, i);
            for (int j = std::max(0, i - t); j <= mpi; ++j) ebpts.row(i) += bezalfs(i, j) * bpts.row(j);
        }
        if (oldr > 1) {
            int first = kind - 2, last = kind;
            const double den = ub - ua;
            const double bet = (ub - Uh[kind - 1]) / den;
            for (int tr = 1; tr < oldr; ++tr) {
                i = first;
                int j = last;
                int kj = j - kind + 1;
                while (j - i > tr) {
                    if (i < cind) {
                        const double alf = (ub - Uh[i]) / (ua - Uh[i]);
                        Q.row(i) = alf * Q.row(i) + (1.0 - alf) * Q.row(i - 1);
                    }
                    if (j >= lbz) {
                        if (j - tr <= kind - ph + oldr) {
                            const double gam = (ub - Uh[j - tr]) / den;
                            ebpts.row(kj) = gam * ebpts.row(kj) + (1.0 - gam) * ebpts.row(kj + 1);
                        } else {
                            ebpts.row(kj) = bet * ebpts.row(kj) + (1.0 - bet) * ebpts.row(kj + 1);
                        }
                    }
                    ++i;
                    --j;
                    --kj;
                }
                --first;
                ++last;
            }
        }
        if (a != p) {
            for (i = 0; i < ph - oldr; ++i) Uh[kind++] = ua;
        }
        for (int j = lbz; j <= rbz; ++j) Q.row(cind++) = ebpts.row(j);
        if (b < m) {
            for (int j = 0; j < r; ++j) bpts.row(j) = nextbpts.row(j);
            for (int j = r; j <= p; ++j) bpts.row(j) = P.row(b - p + j);
            a = b;
            ++b;
            ua = ub;
        } else {
            for (i = 0; i <= ph; ++i) Uh[kind + i] = ub;
        }
    }
    const int nh = mh - ph - 1;
    KnotsAndPoints out;
    out.knots.assign(Uh.begin(), Uh.begin() + nh + ph + 2);
    out.points = Q.topRows(nh + 1);
    return out;
}

RemovalResult removeKnot(int p, KnotVector& U, ControlMatrix& P, double u, int num, double tol, int groupSize)
{
    RemovalResult result;
    checkInsideDomain(p, U, u, "knot to remove");
    const int s = knotMultiplicity(U, u);
    if (s == 0) throw GeometryError("knot to remove: " + std::to_string(u) + " is not a knot");
    num = std::min(num, s);
    // The NURBS Book, A5.8. r: the last index of u.
    const int n = static_cast<int>(P.rows()) - 1;
    const int m = n + p + 1;
    const int r = static_cast<int>(std::upper_bound(U.begin(), U.end(), u) - U.begin()) - 1;
    const int ord = p + 1;
    const int fout = (2 * r - s - p) / 2;
    int last = r - s;
    int first = r - p;
    ControlMatrix temp(2 * p + 1, P.cols());
    int t = 0;
    for (t = 0; t < num; ++t) {
        const int off = first - 1;
        temp.row(0) = P.row(off);
        temp.row(last + 1 - off) = P.row(last + 1);
        int i = first, j = last, ii = 1, jj = last - off;
        while (j - i > t) {
            const double alfi = (u - U[i]) / (U[i + ord + t] - U[i]);
            const double alfj = (u - U[j - t]) / (U[j + ord] - U[j - t]);
            temp.row(ii) = (P.row(i) - (1.0 - alfi) * temp.row(ii - 1)) / alfi;
            temp.row(jj) = (P.row(j) - alfj * temp.row(jj + 1)) / (1.0 - alfj);
            ++i;
            ++ii;
            --j;
            --jj;
        }
        double d = 0.0;
        if (j - i < t) {
            d = groupDistance(temp.row(ii - 1), temp.row(jj + 1), groupSize);
        } else {
            const double alfi = (u - U[i]) / (U[i + ord + t] - U[i]);
            d = groupDistance(P.row(i), alfi * temp.row(ii + t + 1) + (1.0 - alfi) * temp.row(ii - 1), groupSize);
        }
        if (!(result.errorBound + d <= tol)) break;
        result.errorBound += d;
        i = first;
        j = last;
        while (j - i > t) {
            P.row(i) = temp.row(i - off);
            P.row(j) = temp.row(j - off);
            ++i;
            --j;
        }
        --first;
        ++last;
    }
    result.removed = t;
    if (t == 0) return result;
    for (int k = r + 1; k <= m; ++k) U[k - t] = U[k];
    U.resize(U.size() - t);
    int j = fout, i = fout;
    for (int k = 1; k < t; ++k) {
        if (k % 2 == 1) ++i;
        else --j;
    }
    for (int k = i + 1; k <= n; ++k) P.row(j++) = P.row(k);
    P.conservativeResize(P.rows() - t, Eigen::NoChange);
    return result;
}

double removalBudget(const ControlMatrix& points, int dim, bool rational, double tolerance)
{
    const int group = dim + (rational ? 1 : 0);
    double wmin = std::numeric_limits<double>::infinity(), pmax = 0.0;
    for (Eigen::Index r = 0; r < points.rows(); ++r) {
        for (Eigen::Index c = 0; c + group <= points.cols(); c += group) {
            const double w = rational ? points(r, c + dim) : 1.0;
            wmin = std::min(wmin, w);
            pmax = std::max(pmax, points.row(r).segment(c, dim).norm() / w);
        }
    }
    const double floor = kRemovalRoundOff * (1.0 + pmax);
    const double budget = rational ? tolerance * wmin / (1.0 + pmax) : tolerance;
    return std::max(budget, floor);
}

int removeKnotsWithinBudget(int degree, KnotVector& knots, ControlMatrix& points, double& budget, int groupSize)
{
    int count = 0;
    bool progress = true;
    while (progress && budget > 0) {
        progress = false;
        for (double u : interiorBreakpoints(degree, knots)) {
            if (static_cast<int>(points.rows()) <= degree + 1) break;
            const RemovalResult r = removeKnot(degree, knots, points, u, 1, budget, groupSize);
            if (r.removed > 0) {
                budget -= r.errorBound;
                count += r.removed;
                progress = true;
            }
        }
    }
    return count;
}

}  // namespace sculptline::solvers
