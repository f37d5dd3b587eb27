#include "solvers/deformation/constraint_geometry.h"

#include "solvers/bspline/arc_length.h"
#include "solvers/bspline/geometry_error.h"
#include "solvers/math_constants.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <optional>

namespace sculptline::solvers::deformation {
namespace {

// A Curve constraint's key points: one more per this much turning of the target (eq. 6-24 asks
// for more key points where the curve bends; π/8 keeps a quarter circle at four extra points).
constexpr double kTurningPerKeyPoint = kPi / 8.0;

// A constraint whose linear rows are met but whose geometric residual exceeds this (radians, or
// model units per unit of the net's size) is reported as not met: e.g. S_u·n = 0 can be reached by
// S_u collapsing to zero, which leaves the normal undefined. Met constraints sit at 1e-13 or below.
constexpr double kUnmetTolerance = 1e-7;

int spanIndex(const Surface3d& s, Direction d, double t) { return findSpan(s.degree(d), s.knots(d), t); }

template <int Dim>
double turning(const BSplineCurve<Dim>& c)
{
    constexpr int kSamples = 64;
    double total = 0.0;
    Eigen::Matrix<double, Dim, 1> prev = Eigen::Matrix<double, Dim, 1>::Zero();
    for (int k = 0; k <= kSamples; ++k) {
        const double t = c.domainStart() + (c.domainEnd() - c.domainStart()) * k / kSamples;
        const Eigen::Matrix<double, Dim, 1> d = c.derivatives(t, 1)[1];
        if (d.norm() == 0.0) continue;
        if (prev.norm() > 0.0) total += std::acos(std::clamp(prev.normalized().dot(d.normalized()), -1.0, 1.0));
        prev = d;
    }
    return total;
}

}  // namespace

namespace detail {


std::string at(size_t c) { return "constraints[" + std::to_string(c) + "]"; }

void requireInDomain(const Surface3d& s, const Eigen::Vector2d& uv, const std::string& field)
{
    if (!uv.allFinite()) throw GeometryError(field + ": not a finite number");
    const double u0 = s.domainStart(Direction::U), u1 = s.domainEnd(Direction::U);
    const double v0 = s.domainStart(Direction::V), v1 = s.domainEnd(Direction::V);
    if (uv.x() < u0 || uv.x() > u1 || uv.y() < v0 || uv.y() > v1) {
        throw GeometryError(field + ": (" + std::to_string(uv.x()) + ", " + std::to_string(uv.y()) +
                            ") is outside the surface's domain [" + std::to_string(u0) + ", " + std::to_string(u1) +
                            "] x [" + std::to_string(v0) + ", " + std::to_string(v1) + "]");
    }
}

// Coefficients of ∂^(du+dv) S / ∂u^du ∂v^dv at (u, v) on the control points (du + dv ≤ 1).
// Rational surfaces keep their weights, so the rows stay linear in the Cartesian points:
// R = A / W with A = w N_i N_j, R_u = (A_u − R W_u) / W (The NURBS Book eq. 4.9, as in
// curve_manipulation.cpp).
Coefficients basisCoefficients(const Surface3d& s, double u, double v, int du, int dv)
{
    const int p = s.degreeU(), q = s.degreeV();
    const int su = findSpan(p, s.knotsU(), u), sv = findSpan(q, s.knotsV(), v);
    double nu[2 * (kMaxDegree + 1)], nv[2 * (kMaxDegree + 1)];
    basisDerivatives(su, u, p, 1, s.knotsU(), nu);
    basisDerivatives(sv, v, q, 1, s.knotsV(), nv);
    Coefficients out;
    out.reserve(static_cast<size_t>((p + 1) * (q + 1)));
    auto value = [&](int a, int b, int ku, int kv) { return nu[ku * (p + 1) + a] * nv[kv * (q + 1) + b]; };
    if (!s.isRational()) {
        for (int a = 0; a <= p; ++a) {
            for (int b = 0; b <= q; ++b) out.emplace_back((su - p + a) * s.countV() + sv - q + b, value(a, b, du, dv));
        }
        return out;
    }
    double W = 0.0, Wd = 0.0;
    for (int a = 0; a <= p; ++a) {
        for (int b = 0; b <= q; ++b) {
            const double w = s.weight(su - p + a, sv - q + b);
            W += w * value(a, b, 0, 0);
            Wd += w * value(a, b, du, dv);
        }
    }
    for (int a = 0; a <= p; ++a) {
        for (int b = 0; b <= q; ++b) {
            const double w = s.weight(su - p + a, sv - q + b);
            const double r = w * value(a, b, 0, 0) / W;
            const double c = (du + dv == 0) ? r : (w * value(a, b, du, dv) - r * Wd) / W;
            out.emplace_back((su - p + a) * s.countV() + sv - q + b, c);
        }
    }
    return out;
}

Coefficients combine(const Coefficients& a, double ca, const Coefficients& b, double cb)
{
    Coefficients out;
    for (const auto& [i, c] : a) out.emplace_back(i, ca * c);
    for (const auto& [i, c] : b) out.emplace_back(i, cb * c);
    return out;
}

// Two unit vectors spanning the plane normal to n.
std::pair<Eigen::Vector3d, Eigen::Vector3d> complement(const Eigen::Vector3d& n)
{
    const Eigen::Vector3d a = std::abs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    const Eigen::Vector3d e1 = n.cross(a).normalized();
    return {e1, n.cross(e1).normalized()};
}

// Spans crossed between two domain points in the dominant direction, counted as in eq. 6-24.
int spansCrossed(const Surface3d& s, const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
    const double wu = s.domainEnd(Direction::U) - s.domainStart(Direction::U);
    const double wv = s.domainEnd(Direction::V) - s.domainStart(Direction::V);
    const bool alongU = std::abs(b.x() - a.x()) / wu >= std::abs(b.y() - a.y()) / wv;
    const Direction d = alongU ? Direction::U : Direction::V;
    const int k = alongU ? 0 : 1;
    return std::abs(spanIndex(s, d, b[k]) - spanIndex(s, d, a[k])) + 1;
}

// Angle (rad) between the lines along a and b, by atan2 (acos loses half the digits near 0).
double angleBetweenLines(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    return std::atan2(a.cross(b).norm(), std::abs(a.dot(b)));
}

std::vector<double> uniformParameters(double t0, double t1, int m)
{
    std::vector<double> t(static_cast<size_t>(m));
    for (int k = 0; k < m; ++k) t[static_cast<size_t>(k)] = m == 1 ? 0.5 * (t0 + t1) : t0 + (t1 - t0) * k / (m - 1);
    return t;
}

// Parameters of m points evenly spaced along c's length, its ends exactly at the domain's ends:
// where the key points fall is then a property of the target's shape, not of how the curve
// happens to be parametrized (a stroke fitted with 4 control points and one with 13 can be the same
// shape within a pixel at speeds differing by 2x, which moved key points together in the surface's
// domain and made the collocation swing the net: the fish's nose 4.8 -> 9.8 mm).
std::vector<double> arcLengthParameters(const BSplineCurve<3>& c, int m)
{
    const ArcLengthParameterization<3> arc(c);
    const double length = arc.totalLength();
    if (!(length > 0.0) || !std::isfinite(length)) return uniformParameters(c.domainStart(), c.domainEnd(), m);
    std::vector<double> out(static_cast<size_t>(m));
    for (int k = 0; k < m; ++k) {
        if (m > 1 && k == 0) out[0] = c.domainStart();
        else if (m > 1 && k == m - 1) out[static_cast<size_t>(k)] = c.domainEnd();
        else out[static_cast<size_t>(k)] = arc.parameterAt(m == 1 ? 0.5 * length : length * k / (m - 1));
    }
    return out;
}

}  // namespace detail

using namespace detail;


int keyPointCount(const Surface3d& surface, const BSplineCurve<3>& target, const Eigen::Vector2d& footStart,
                  const Eigen::Vector2d& footEnd)
{
    const int bends = static_cast<int>(std::floor(turning(target) / kTurningPerKeyPoint));
    const int spans = spansCrossed(surface, footStart, footEnd);
    // But no more than the net can meet along the feet: the spans crossed hold spans + p basis
    // functions in that direction, and with as many key points as functions, or one fewer, the
    // collocation is so ill-conditioned that the net swings far away to meet them exactly (a fin
    // drawn over a fish's back, 17 key points on 17 functions: control points moved 4.6e5 mm for a
    // 9 mm fin). Two fewer than the functions keeps the solve exact and the change the target's size.
    const double wu = surface.domainEnd(Direction::U) - surface.domainStart(Direction::U);
    const double wv = surface.domainEnd(Direction::V) - surface.domainStart(Direction::V);
    const bool alongU = std::abs(footEnd.x() - footStart.x()) / wu >= std::abs(footEnd.y() - footStart.y()) / wv;
    const int degree = surface.degree(alongU ? Direction::U : Direction::V);
    return std::clamp(std::min(spans + bends, spans + degree - 2), 2, kMaxKeyPoints);
}

KeyPoints curveKeyPoints(const Surface3d& surface, const SurfaceConstraint& k, const SurfaceProjector* projector)
{
    if (!k.target) throw GeometryError("target: a curve constraint needs a target curve");
    const BSplineCurve<3>& H = *k.target;
    KeyPoints out;
    if (k.domain) {
        const BSplineCurve<2>& G = *k.domain;
        const Eigen::Vector2d a = G.evaluate(G.domainStart()), b = G.evaluate(G.domainEnd());
        const int count = std::min(kMaxKeyPoints, k.keyPoints > 0 ? k.keyPoints : keyPointCount(surface, H, a, b));
        for (double t : uniformParameters(G.domainStart(), G.domainEnd(), count)) {
            const double s = (t - G.domainStart()) / (G.domainEnd() - G.domainStart());
            out.uv.push_back(G.evaluate(t));
            out.t.push_back(H.domainStart() + s * (H.domainEnd() - H.domainStart()));
        }
        return out;
    }
    // Feet of the key points by global projection (thesis §6.2.5: K_s, K_e → P_s, P_e).
    std::optional<SurfaceProjector> own;
    if (!projector) projector = &own.emplace(surface);
    const auto footOf = [&](double t) {
        const SurfaceProjection f = projector->project(H.evaluate(t));
        return Eigen::Vector2d(f.u, f.v);
    };
    const int count = std::min(kMaxKeyPoints, k.keyPoints > 0 ? k.keyPoints
                                                              : keyPointCount(surface, H, footOf(H.domainStart()),
                                                                              footOf(H.domainEnd())));
    for (double t : arcLengthParameters(H, count)) {
        out.uv.push_back(footOf(t));
        out.t.push_back(t);
    }
    return out;
}

void flagUnmet(const Surface3d& surface, const std::vector<SurfaceConstraint>& constraints, DeformationReport& report)
{
    if (report.compromise) return;
    Eigen::AlignedBox3d box;
    for (const auto& p : surface.points()) box.extend(p);
    const double size = std::max(1.0, box.diagonal().norm());
    for (size_t c = 0; c < report.residuals.size() && c < constraints.size(); ++c) {
        const bool angle = constraints[c].type == SurfaceConstraintType::Normal ||
                           constraints[c].type == SurfaceConstraintType::CurveTangent ||
                           constraints[c].type == SurfaceConstraintType::Tangents ||
                           constraints[c].type == SurfaceConstraintType::Angle;
        const double limit = angle ? kUnmetTolerance : kUnmetTolerance * size;
        if (report.residuals[c] > limit) {
            report.compromise = true;
            report.message = at(c) + " is not met (residual " + std::to_string(report.residuals[c]) +
                             "): its linear rows hold but the geometry does not follow them (a tangent " +
                             "collapsed, or the distance steps did not converge)";
            return;
        }
    }
}

std::vector<double> constraintResiduals(const Surface3d& before, const Surface3d& after,
                                        const std::vector<SurfaceConstraint>& factored,
                                        const std::vector<SurfaceConstraint>& constraints,
                                        const std::vector<std::vector<Eigen::Vector2d>>& keyUv,
                                        const std::vector<std::vector<double>>& keyT, double lambda)
{
    std::vector<double> out(constraints.size(), 0.0);
    auto lengthError = [&](size_t c) {
        const SurfaceConstraint& k = constraints[c];
        const double now = (after.evaluate(k.uv2.x(), k.uv2.y()) - after.evaluate(k.uv.x(), k.uv.y())).norm();
        const double start = (before.evaluate(k.uv2.x(), k.uv2.y()) - before.evaluate(k.uv.x(), k.uv.y())).norm();
        return start + lambda * (k.distance - start) - now;
    };
    for (size_t c = 0; c < constraints.size(); ++c) {
        const SurfaceConstraint& k = constraints[c];
        double res = 0.0;
        switch (k.type) {
            case SurfaceConstraintType::Position: {
                const Eigen::Vector3d start = before.evaluate(k.uv.x(), k.uv.y());
                res = (after.evaluate(k.uv.x(), k.uv.y()) - (start + lambda * (k.value - start))).norm();
                break;
            }
            case SurfaceConstraintType::Curve:
                for (size_t p = 0; p < keyUv[c].size(); ++p) {
                    const Eigen::Vector2d& uv = keyUv[c][p];
                    const Eigen::Vector3d start = before.evaluate(uv.x(), uv.y());
                    const Eigen::Vector3d goal = start + lambda * (k.target->evaluate(keyT[c][p]) - start);
                    res = std::max(res, (after.evaluate(uv.x(), uv.y()) - goal).norm());
                }
                break;
            case SurfaceConstraintType::Normal: {
                // λ = 1: the angle (rad) between the normal and ±value; λ < 1: the rows'
                // residual S_u·n − (1 − λ) S_u°·n over |S_u| (the sine of the angle left over).
                const Eigen::Vector3d nrm = factored[c].value.normalized();
                const auto now = after.derivatives(k.uv.x(), k.uv.y(), 1);
                const auto was = before.derivatives(k.uv.x(), k.uv.y(), 1);
                const double ru = (now[1][0].dot(nrm) - (1.0 - lambda) * was[1][0].dot(nrm)) / now[1][0].norm();
                const double rv = (now[0][1].dot(nrm) - (1.0 - lambda) * was[0][1].dot(nrm)) / now[0][1].norm();
                if (lambda == 1.0) {
                    res = angleBetweenLines(after.normal(k.uv.x(), k.uv.y()), nrm);
                } else {
                    res = std::hypot(ru, rv);
                }
                break;
            }
            case SurfaceConstraintType::CurveTangent: {
                // λ = 1: the largest angle (rad) between the cross tangent and the line of value;
                // λ < 1: the rows' residual e·X − (1 − λ) e·X° over |X| (as for Normal).
                const Eigen::Vector3d dir = factored[c].value.normalized();
                const auto [e1, e2] = complement(dir);
                for (size_t p = 0; p < keyUv[c].size(); ++p) {
                    // The factored domain: a drag's per-event constraints carry values only.
                    const Eigen::Vector2d g1 = factored[c].domain->derivatives(keyT[c][p], 1)[1];
                    const Eigen::Vector2d across = Eigen::Vector2d(-g1.y(), g1.x()).normalized();
                    const Eigen::Vector2d& uv = keyUv[c][p];
                    const auto der = after.derivatives(uv.x(), uv.y(), 1);
                    const auto was = before.derivatives(uv.x(), uv.y(), 1);
                    const Eigen::Vector3d cross = across.x() * der[1][0] + across.y() * der[0][1];
                    const Eigen::Vector3d cross0 = across.x() * was[1][0] + across.y() * was[0][1];
                    if (cross.norm() == 0.0) {
                        res = std::max(res, kPi / 2);  // collapsed: no direction at all
                    } else if (lambda == 1.0) {
                        res = std::max(res, angleBetweenLines(cross, dir));
                    } else {
                        res = std::max(res, std::hypot(e1.dot(cross) - (1.0 - lambda) * e1.dot(cross0),
                                                       e2.dot(cross) - (1.0 - lambda) * e2.dot(cross0)) /
                                                cross.norm());
                    }
                }
                break;
            }
            case SurfaceConstraintType::Tangents: {
                // Relative: |S_u − goal_u| / |goal_u|, the larger of u and v (the sine of the angle
                // off, for a small one), dimensionless like the angles.
                const auto now = after.derivatives(k.uv.x(), k.uv.y(), 1);
                const auto was = before.derivatives(k.uv.x(), k.uv.y(), 1);
                const Eigen::Vector3d gu = was[1][0] + lambda * (k.value - was[1][0]);
                const Eigen::Vector3d gv = was[0][1] + lambda * (k.value2 - was[0][1]);
                res = std::max((now[1][0] - gu).norm() / std::max(gu.norm(), 1e-300),
                               (now[0][1] - gv).norm() / std::max(gv.norm(), 1e-300));
                break;
            }
            case SurfaceConstraintType::Distance:
                res = std::abs(lengthError(c));
                break;
            case SurfaceConstraintType::Angle: {
                // λ = 1: radians between the angle reached and the one asked for; λ < 1: Normal's
                // row measure with the goal normal n* of factor() (value2).
                const Eigen::Vector3d a = factored[c].value.normalized(), goal = factored[c].value2;
                if (lambda == 1.0) {
                    res = std::abs(std::acos(std::clamp(after.normal(k.uv.x(), k.uv.y()).dot(a), -1.0, 1.0)) - k.angle);
                } else {
                    const auto now = after.derivatives(k.uv.x(), k.uv.y(), 1);
                    const auto was = before.derivatives(k.uv.x(), k.uv.y(), 1);
                    res = std::hypot((now[1][0].dot(goal) - (1.0 - lambda) * was[1][0].dot(goal)) / now[1][0].norm(),
                                     (now[0][1].dot(goal) - (1.0 - lambda) * was[0][1].dot(goal)) / now[0][1].norm());
                }
                break;
            }
        }
        out[c] = res;
    }
    return out;
}

}  // namespace sculptline::solvers::deformation
