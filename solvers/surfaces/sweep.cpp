#include "solvers/surfaces/sweep.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/math_constants.h"
#include "solvers/surfaces/approximation_tolerance.h"
#include "solvers/surfaces/rotation_minimizing_frames.h"

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

namespace sculptline::solvers::surfaces {

using Vec3 = Eigen::Vector3d;

/// The path sampled for sweeping: frames at every section and probe (kProbes per interval between
/// sections), and at each section the path's derivative and the frames' angular velocity.
struct SweepPathSamples {
    double a = 0.0, b = 1.0;
    std::vector<double> breaks;   // the path's distinct knots in the domain
    std::vector<int> perSpan;     // sections per path knot span
    std::vector<double> params;   // sections and probes
    std::vector<int> spanOf;      // path knot span of each interval between sections
    std::vector<Frame> frames;    // at params
    std::vector<Vec3> d1, omega;  // at the sections, params[kProbes * k]
    Vec3 x0 = Vec3::Zero();       // the path's start

    int sections() const { return static_cast<int>(d1.size()); }
    /// The samples of the path moved by x -> R x + t.
    void transform(const Eigen::Matrix3d& R, const Vec3& t)
    {
        for (Frame& f : frames) {
            f.origin = R * f.origin + t;
            f.tangent = R * f.tangent;
            f.normal = R * f.normal;
            f.binormal = R * f.binormal;
        }
        for (Vec3& d : d1) d = R * d;
        for (Vec3& w : omega) w = R * w;
        x0 = R * x0 + t;
    }
};

namespace {

// Profile samples per control point when measuring the deviation between sections.
constexpr int kProfileSamplesPerPoint = 2;
// Sections per path knot span to start from.
constexpr int kInitialPerSpan = 2;
// Probes per interval between sections: the interpolation error peaks inside each interval, not
// necessarily at its middle; quarter points bound it to within a few percent.
constexpr int kProbes = 4;
// The C1 cubic Hermite error falls as h^4 (de Boor, "A Practical Guide to Splines", ch. IV): a
// span r times over tolerance needs r^(1/4) times the sections; the margin covers the estimate's
// error (the probes, and the frames' own O(h^4) error) so that one more pass is rarely needed.
constexpr double kGrowthMargin = 1.25;
// A path whose control points a rigid motion maps onto the new ones to this fraction of its size
// has moved rigidly (round-off of a plane's transform is ~1e-16).
constexpr double kRigidRelative = 1e-10;
constexpr double kSinglePointRelative = 1e-12;
// The left-hand tangent at a knot, from this fraction of the domain before it (a polynomial piece's
// derivative is continuous inside its span, so the angle is off by about this much).
constexpr double kLeftOfKnot = 1e-9;

// A path closes smoothly when its ends coincide to round-off and its end tangents agree to this
// angle (radians): a periodic curve's seam is C^(p-1), so its tangents agree to round-off.
constexpr double kSmoothSeam = 1e-6;
constexpr double kSeamGapRelative = 1e-9;

bool closesSmoothly(const CurveJet3d& jet, double a, double b, double size)
{
    Vec3 x0, t0, d2, x1, t1;
    jet.evaluate(a, x0, t0, d2);
    jet.evaluate(b, x1, t1, d2);
    return (x1 - x0).norm() <= kSeamGapRelative * size && t0.normalized().cross(t1.normalized()).norm() <= kSmoothSeam &&
           t0.dot(t1) > 0.0;
}

std::shared_ptr<SweepPathSamples> samplePath(const CurveJet3d& jet, const std::vector<double>& breaks,
                                             const std::vector<int>& perSpan, bool closed)
{
    auto s = std::make_shared<SweepPathSamples>();
    s->a = breaks.front();
    s->b = breaks.back();
    s->breaks = breaks;
    s->perSpan = perSpan;
    for (size_t span = 0; span + 1 < breaks.size(); ++span) {
        const int m = kProbes * perSpan[span];
        for (int k = 0; k < m; ++k) s->params.push_back(breaks[span] + (breaks[span + 1] - breaks[span]) * k / m);
        for (int k = 0; k < perSpan[span]; ++k) s->spanOf.push_back(static_cast<int>(span));
    }
    s->params.push_back(s->b);
    Vec3 x, d1, d2;
    jet.evaluate(s->a, x, d1, d2);
    s->x0 = x;
    // Reference normal: any direction off the tangent; the swept shape does not depend on it (an
    // RMF rotated about t0 rotates every frame alike).
    s->frames = rotationMinimizingFrames(jet, s->params, d1.normalized().unitOrthogonal());
    // On a closed path the rotation-minimizing frame returns rotated about the tangent by the
    // path's holonomy angle φ; turning frame v back by φ·v closes the sweep at the path's seam
    // (Wang et al. 2008, §6, "closed curves"), adding -φ/(b - a) about T to the angular velocity.
    double twistRate = 0.0;
    if (closed) {
        const Frame& first = s->frames.front();
        const Frame& last = s->frames.back();
        const double phi = std::atan2(first.normal.cross(last.normal).dot(first.tangent), first.normal.dot(last.normal));
        twistRate = -phi / (s->b - s->a);
        for (size_t k = 0; k < s->frames.size(); ++k) {
            Frame& f = s->frames[k];
            const double psi = twistRate * (s->params[k] - s->a);
            f.normal = std::cos(psi) * f.normal + std::sin(psi) * f.binormal;
            f.binormal = f.tangent.cross(f.normal);
        }
    }
    for (size_t k = 0; k < s->params.size(); k += kProbes) {
        jet.evaluate(s->params[k], x, d1, d2);
        // d/dt of x(t) + M(t)(P - x0) is x'(t) + ω × M(P - x0), ω = T × dT/dt, the angular
        // velocity of a rotation-minimizing frame (no component along T; Bishop 1975).
        const double speed = d1.norm();
        const Vec3 T = d1 / speed;
        const Vec3 dT = (d2 - d2.dot(T) * T) / speed;
        s->d1.push_back(d1);
        s->omega.push_back(T.cross(dT) + twistRate * T);
    }
    return s;
}

// The profile (clamped) with its samples for the deviation check, relative to the path's start.
struct ProfileSamples {
    const Curve3d& profile;
    int n, h, pu;
    std::vector<Vec3> points;  // profile(u_i) - x0
    std::vector<int> span;
    std::vector<double> basis;  // (pu + 1) per sample (The NURBS Book A2.1, A2.2)

    ProfileSamples(const Curve3d& c, const Vec3& x0)
        : profile(c), n(c.pointCount()), h(c.isRational() ? 4 : 3), pu(c.degree())
    {
        const int us = kProfileSamplesPerPoint * n;
        basis.resize(static_cast<size_t>(us + 1) * (pu + 1));
        for (int i = 0; i <= us; ++i) {
            const double u = c.domainStart() + (c.domainEnd() - c.domainStart()) * i / us;
            points.push_back(c.evaluate(u) - x0);
            span.push_back(findSpan(pu, c.knots(), u));
            basisFunctions(span.back(), u, pu, c.knots(), &basis[static_cast<size_t>(i) * (pu + 1)]);
        }
    }
};

struct Assembly {
    ControlMatrix net;
    KnotVector knotsV;
    std::vector<double> spanDeviation;  // per path knot span
    double deviation = 0.0;
};

// The C1 cubic net (double knots at the inner sections: S_k, then S_k ± h/3·S'_k) and its
// deviation from the exact sweep at the probes.
Assembly assemble(const ProfileSamples& P, const SweepPathSamples& S)
{
    const int count = S.sections();
    const int n = P.n, h = P.h;
    const double a = S.a, b = S.b;
    const Eigen::Matrix3d base = S.frames.front().axes().transpose();
    Assembly out;
    out.net.resize(2 * count, static_cast<Eigen::Index>(n) * h);
    out.knotsV.assign(4, 0.0);
    std::vector<double> v(count);
    for (int k = 0; k < count; ++k) v[k] = (S.params[kProbes * k] - a) / (b - a);
    v.back() = 1.0;
    for (int k = 1; k + 1 < count; ++k) out.knotsV.insert(out.knotsV.end(), 2, v[k]);
    out.knotsV.insert(out.knotsV.end(), 4, 1.0);
    std::vector<Vec3> rel(n);
    for (int k = 0; k < count; ++k) {
        const Frame& f = S.frames[kProbes * k];
        const Eigen::Matrix3d M = f.axes() * base;
        const double hPrev = k > 0 ? v[k] - v[k - 1] : 0.0;
        const double hNext = k + 1 < count ? v[k + 1] - v[k] : 0.0;
        for (int i = 0; i < n; ++i) {
            const double w = P.profile.weight(i);
            const Vec3 r = M * (P.profile.points()[i] - S.x0);
            const Vec3 p = f.origin + r;
            const Vec3 dp = (b - a) * (S.d1[k] + S.omega[k].cross(r));  // d/dv
            const auto put = [&](int row, const Vec3& x) {
                out.net.block(row, static_cast<Eigen::Index>(i) * h, 1, 3) = w * x.transpose();
                if (h == 4) out.net(row, static_cast<Eigen::Index>(i) * h + 3) = w;
            };
            // Rows: S_0, S_0 + h0/3 S'_0, S_1 - h0/3 S'_1, S_1 + h1/3 S'_1, ..., S_last.
            if (k == 0) {
                put(0, p);
                put(1, p + hNext / 3.0 * dp);
            } else if (k + 1 == count) {
                put(2 * k, p - hPrev / 3.0 * dp);
                put(2 * k + 1, p);
            } else {
                put(2 * k, p - hPrev / 3.0 * dp);
                put(2 * k + 1, p + hNext / 3.0 * dp);
            }
        }
    }
    out.spanDeviation.assign(S.breaks.size() - 1, 0.0);
    Eigen::RowVectorXd iso(out.net.cols());
    const int pu = P.pu;
    for (int k = 0; k + 1 < count; ++k) {
        double& worst = out.spanDeviation[S.spanOf[k]];
        for (int q = 1; q < kProbes; ++q) {
            const Frame& f = S.frames[kProbes * k + q];
            const Eigen::Matrix3d M = f.axes() * base;
            const double vm = (S.params[kProbes * k + q] - a) / (b - a);
            // The probe's iso-curve rows (v basis applied to the net), then the fixed u samples.
            const int vSpan = findSpan(3, out.knotsV, vm);
            double nv[4];
            basisFunctions(vSpan, vm, 3, out.knotsV, nv);
            iso.noalias() = nv[0] * out.net.row(vSpan - 3) + nv[1] * out.net.row(vSpan - 2) +
                            nv[2] * out.net.row(vSpan - 1) + nv[3] * out.net.row(vSpan);
            for (size_t i = 0; i < P.points.size(); ++i) {
                const double* N = &P.basis[i * (pu + 1)];
                Eigen::Vector4d hp = Eigen::Vector4d::Zero();
                for (int c = 0; c <= pu; ++c) {
                    const Eigen::Index col = static_cast<Eigen::Index>(P.span[i] - pu + c) * h;
                    hp.head<3>() += N[c] * iso.segment<3>(col).transpose();
                    hp(3) += N[c] * (h == 4 ? iso(col + 3) : 1.0);
                }
                const Vec3 x = hp.head<3>() / hp(3);
                worst = std::max(worst, (x - (f.origin + M * P.points[i])).norm());
            }
        }
        out.deviation = std::max(out.deviation, worst);
    }
    return out;
}

double sweepTolerance(const Curve3d& profile, const Curve3d& path, const SweepOptions& options)
{
    const double size = std::max(profile.controlSize(), path.controlSize());
    return approximationTolerance(options.tolerance, kDefaultSweepRelative * size, coordinateScale({&profile, &path}));
}

SweepResult sweepResult(const Curve3d& profile, Assembly&& A, int sections, double tolerance)
{
    return SweepResult{Surface3d::fromGroupedRows(Direction::V, profile.degree(), 3, profile.knots(),
                                                  std::move(A.knotsV), A.net, profile.isRational()),
                       A.deviation, sections, tolerance};
}

// At a corner of the path (a knot where the tangent turns) the exact sweep is torn: the section
// turns at once with the frame, so points at distance ρ from the path jump by up to 2ρ·sin(α/2).
// Within tolerance the interpolation absorbs it; beyond, no surface follows the construction.
void requireNoTear(const CurveJet3d& jet, const Curve3d& path, const Curve3d& profile, double tolerance)
{
    const double a = path.domainStart(), b = path.domainEnd();
    Vec3 x0, d1, d2;
    jet.evaluate(a, x0, d1, d2);
    double reach = 0.0;  // bound on the profile's distance from the path's start (convex hull)
    for (const Vec3& p : profile.points()) reach = std::max(reach, (p - x0).norm());
    for (double k : interiorBreakpoints(path.degree(), path.knots())) {
        Vec3 x, right, left;
        jet.evaluate(k, x, right, d2);  // right-hand derivative at a knot
        jet.evaluate(k - kLeftOfKnot * (b - a), x, left, d2);
        const double angle = std::acos(std::clamp(left.normalized().dot(right.normalized()), -1.0, 1.0));
        const double tear = 2.0 * reach * std::sin(0.5 * angle);
        if (tear > tolerance)
            throw GeometryError("path: corner at u = " + std::to_string(k) + " (the tangent turns by " +
                                std::to_string(angle * 180.0 / kPi) +
                                " degrees): the swept profile would tear there by up to " + std::to_string(tear) +
                                " (tolerance " + std::to_string(tolerance) + "); round the corner or sweep each side separately");
    }
}

// A polyline path: the rotation-minimizing frame is constant along each segment and turns at a
// vertex by the least rotation R taking one direction to the next. The sections meet in mitres:
// the section before the vertex, projected along the incoming direction onto the bisector plane
// (normal t_in + t_out), is the section after it projected back along t_out (the reflection in the
// bisector plane equals R on the incoming normal plane), so the sweep is exactly the ruled surface
// through start section, mitres and end section. A closed planar polyline (the frame returns
// unturned) is mitred at its seam too, so it closes.
SweepResult polylineSweep(const Curve3d& profile, const Curve3d& path, double tolerance)
{
    const std::vector<Vec3>& Q = path.points();
    const int m = static_cast<int>(Q.size()) - 1;  // segments
    std::vector<Vec3> t;
    for (int k = 0; k < m; ++k) t.push_back((Q[k + 1] - Q[k]).normalized());
    const Vec3 x0 = Q.front();
    const bool loop = (Q.back() - Q.front()).norm() <= kSeamGapRelative * path.controlSize() && m > 1;
    // Relative transforms of the sections on each segment, M_k = R_k ... R_1.
    std::vector<Eigen::Matrix3d> M{Eigen::Matrix3d::Identity()};
    for (int k = 1; k < m; ++k) M.push_back(Eigen::Quaterniond::FromTwoVectors(t[k - 1], t[k]).toRotationMatrix() * M.back());
    const Eigen::Matrix3d closing = Eigen::Quaterniond::FromTwoVectors(t[m - 1], t[0]).toRotationMatrix() * M.back();
    const bool mitreSeam = loop && closing.isIdentity(1e-9);
    const auto mitre = [](const Vec3& r, const Vec3& in, const Vec3& out) {
        const Vec3 bisector = (in + out).normalized();
        return Vec3(r - bisector.dot(r) / bisector.dot(in) * in);
    };
    const int n = profile.pointCount();
    const int h = profile.isRational() ? 4 : 3;
    ControlMatrix rows(m + 1, static_cast<Eigen::Index>(n) * h);
    for (int i = 0; i < n; ++i) {
        const Vec3 rel = profile.points()[i] - x0;
        for (int k = 0; k <= m; ++k) {
            Vec3 x;
            if (k == 0 || k == m) {
                // The ends: the profile as it lies and its copy on the last segment, or the seam's mitre.
                x = mitreSeam ? Vec3(x0 + mitre(M.back() * rel, t[m - 1], t[0]))
                              : Vec3(k == 0 ? profile.points()[i] : Vec3(Q[m] + M.back() * rel));
            } else {
                x = Q[k] + mitre(M[k - 1] * rel, t[k - 1], t[k]);
            }
            const double w = profile.weight(i);
            rows.block(k, static_cast<Eigen::Index>(i) * h, 1, 3) = w * x.transpose();
            if (h == 4) rows(k, static_cast<Eigen::Index>(i) * h + 3) = w;
        }
    }
    KnotVector knotsV = path.knots();
    const double a = path.domainStart(), b = path.domainEnd();
    for (double& v : knotsV) v = (v - a) / (b - a);
    return SweepResult{Surface3d::fromGroupedRows(Direction::V, profile.degree(), 1, profile.knots(), knotsV, rows,
                                                  profile.isRational()),
                       0.0, m + 1, tolerance};
}

SweepResult buildSweep(const Curve3d& profile, const Curve3d& path, const SweepOptions& options,
                       std::shared_ptr<SweepPathSamples>& samples)
{
    requireNoCusp(path);
    // A profile this much smaller than the path sweeps out a curve, not a surface.
    if (!(profile.controlSize() > kSinglePointRelative * std::max(1.0, path.controlSize())))
        throw GeometryError("curves: the profile is a single point, sweeping it gives no surface");
    const double tolerance = sweepTolerance(profile, path, options);
    if (path.degree() == 1) {
        samples.reset();
        return polylineSweep(profile, path, tolerance);
    }
    const CurveJet3d jet(path);
    requireNoTear(jet, path, profile, tolerance);
    // Sections at equally spaced parameters per path knot span, so every path knot (where the
    // exact sweep is only C1) is a section: C1 in v, error O(h^4) on each piece instead of the
    // O(h^2) a C2 interpolant gets across the C1 knots.
    std::vector<double> breaks{path.domainStart()};
    for (double k : interiorBreakpoints(path.degree(), path.knots())) breaks.push_back(k);
    breaks.push_back(path.domainEnd());
    const int spans = static_cast<int>(breaks.size()) - 1;
    const int budget = std::max(spans, options.maxSections - 1);  // intervals between sections
    std::vector<int> perSpan(spans, std::max(1, std::min(kInitialPerSpan, budget / spans)));
    const bool closed = closesSmoothly(jet, breaks.front(), breaks.back(), path.controlSize());
    for (;;) {
        samples = samplePath(jet, breaks, perSpan, closed);
        const ProfileSamples P(profile, samples->x0);
        Assembly A = assemble(P, *samples);
        // Grow the spans over tolerance by the h^4 estimate, within the budget.
        std::vector<int> next = perSpan;
        for (int s = 0; s < spans; ++s)
            if (A.spanDeviation[s] > tolerance) {
                const double factor = std::pow(kGrowthMargin * A.spanDeviation[s] / tolerance, 0.25);
                // Capped as a double (beyond the budget it is shared out below anyway): a profile
                // point at 1e91 asked for 2.6e23 sections, which overflowed int.
                const double grown = std::ceil(perSpan[s] * factor);
                next[s] = std::max(perSpan[s] + 1, grown <= budget ? static_cast<int>(grown) : budget + 1);
            }
        int total = 0, wanted = 0;
        for (int s = 0; s < spans; ++s) {
            total += perSpan[s];
            wanted += next[s];
        }
        if (wanted > budget && wanted > total) {
            // Share what the budget allows in proportion to each span's growth.
            const double share = static_cast<double>(budget - total) / (wanted - total);
            for (int s = 0; s < spans; ++s) next[s] = perSpan[s] + static_cast<int>(std::floor((next[s] - perSpan[s]) * share));
        }
        if (A.deviation <= tolerance || next == perSpan) return sweepResult(profile, std::move(A), samples->sections(), tolerance);
        perSpan = next;
    }
}

// The rigid motion x -> R x + t taking `from`'s control points onto `to`'s (Kabsch's SVD fit), if
// the two curves have the same knots and weights and the fit is exact to kRigidRelative.
std::optional<std::pair<Eigen::Matrix3d, Vec3>> rigidMotion(const Curve3d& from, const Curve3d& to)
{
    if (from.degree() != to.degree() || from.knots() != to.knots() || from.weights() != to.weights()) return std::nullopt;
    const std::vector<Vec3>& p = from.points();
    const std::vector<Vec3>& q = to.points();
    if (p == q) return std::make_pair(Eigen::Matrix3d(Eigen::Matrix3d::Identity()), Vec3(Vec3::Zero()));
    Vec3 cp = Vec3::Zero(), cq = Vec3::Zero();
    for (size_t k = 0; k < p.size(); ++k) {
        cp += p[k];
        cq += q[k];
    }
    cp /= static_cast<double>(p.size());
    cq /= static_cast<double>(q.size());
    Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
    for (size_t k = 0; k < p.size(); ++k) H += (p[k] - cp) * (q[k] - cq).transpose();
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix3d D = Eigen::Matrix3d::Identity();
    D(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
    const Eigen::Matrix3d R = svd.matrixV() * D * svd.matrixU().transpose();
    const Vec3 t = cq - R * cp;
    const double size = std::max(from.controlSize(), to.controlSize());
    for (size_t k = 0; k < p.size(); ++k)
        if (!((R * p[k] + t - q[k]).norm() <= kRigidRelative * size)) return std::nullopt;
    return std::make_pair(R, t);
}

}  // namespace

SweepResult sweep(const Curve3d& input, const Curve3d& inputPath, const SweepOptions& options)
{
    std::shared_ptr<SweepPathSamples> samples;
    return buildSweep(input.clamped(), inputPath.clamped(), options, samples);
}

SweepBuilder::SweepBuilder(const Curve3d& profile, const Curve3d& path, const SweepOptions& options) : options_(options)
{
    reset(profile, path);
}

const SweepResult& SweepBuilder::reset(const Curve3d& profile, const Curve3d& path)
{
    auto clampedPath = std::make_unique<Curve3d>(path.clamped());
    result_ = std::make_unique<SweepResult>(buildSweep(profile.clamped(), *clampedPath, options_, samples_));
    path_ = std::move(clampedPath);
    return *result_;
}

const SweepResult& SweepBuilder::update(const Curve3d& inputProfile, const Curve3d& inputPath)
{
    const Curve3d path = inputPath.clamped();
    const std::optional<std::pair<Eigen::Matrix3d, Vec3>> motion = rigidMotion(*path_, path);
    if (!motion || !samples_) return reset(inputProfile, inputPath);  // (polyline sweeps keep no samples)
    if (!motion->first.isIdentity(0.0) || !motion->second.isZero(0.0)) {
        samples_->transform(motion->first, motion->second);
        *path_ = path;
    }
    const Curve3d profile = inputProfile.clamped();
    const double tolerance = sweepTolerance(profile, path, options_);
    Assembly A = assemble(ProfileSamples(profile, samples_->x0), *samples_);
    if (A.deviation > tolerance) return reset(inputProfile, inputPath);
    result_ = std::make_unique<SweepResult>(sweepResult(profile, std::move(A), samples_->sections(), tolerance));
    return *result_;
}

}  // namespace sculptline::solvers::surfaces
