#include "solvers/surfaces/rail_rotation.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/bspline/periodic.h"
#include "solvers/bspline/projection.h"
#include "solvers/math_constants.h"
#include "solvers/surfaces/approximation_tolerance.h"
#include "solvers/surfaces/compatible_curves.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>

namespace sculptline::solvers::surfaces {

namespace {

using Vec3 = Eigen::Vector3d;

// Rail samples bracketing the angle; the bracket is then refined to round-off.
constexpr int kRailSamples = 720;
constexpr int kRootSteps = 100;
constexpr double kParameterResolution = 1e-15;  // below the round-off of parameters in [0, 1]
// The profile's ends and the rails' ends must meet within 1e-3 of the model's size (about a pixel
// when the model spans the viewport: what a sketched stroke that snapped to a curve achieves).
constexpr double kMeetRelative = 1e-3;
// A rail whose total turn about the axis differs from a full turn by more than this is not closed
// around the axis (radians; a generous margin for round-off of the unwrapped angles).
constexpr double kFullTurnSlack = 0.1;
// A decrease of the unwrapped angle beyond this (radians) means a half-plane cuts the rail twice.
constexpr double kMonotoneSlack = 1e-9;
constexpr int kInitialSections = 16;
// Margin on the h^4 estimate of the sections needed, so that one more pass is rarely needed.
constexpr double kGrowthMargin = 1.25;
// Probes between neighbouring sections: the interpolation error peaks inside each interval, not
// necessarily at its middle; quarter points bound it to within a few percent.
constexpr int kProbesPerInterval = 4;

struct AxisFrame {
    Vec3 origin, dir, e1, e2;
    double angle(const Vec3& x) const { return std::atan2((x - origin).dot(e2), (x - origin).dot(e1)); }
};

Vec3 boxCentre(const Curve3d& c)
{
    Eigen::AlignedBox3d box;
    for (int k = 0; k <= kRailSamples; ++k) box.extend(c.evaluate(static_cast<double>(k) / kRailSamples));
    return box.center();
}

double wrapNear(double a, double reference)
{
    while (a - reference > kPi) a -= 2 * kPi;
    while (a - reference < -kPi) a += 2 * kPi;
    return a;
}

// A rail opened at the point nearest to the profile's end, with its unwrapped angle about the axis.
class Rail {
public:
    Rail(const Curve3d& c, const Vec3& start, const AxisFrame& axis, double meet, const std::string& name)
        : curve_(normalizedCurve(c)), axis_(axis), name_(name)
    {
        if ((curve_.evaluate(0.0) - curve_.evaluate(1.0)).norm() > meet)
            throw GeometryError(name + ": the rail is not closed");
        const CurveProjection<3> p = projectToCurve(curve_, start);
        if (p.distance > meet)
            throw GeometryError("curves[2]: the profile does not reach " + name + " (gap " + std::to_string(p.distance) + ")");
        v0_ = p.u;
        a0_ = axis.angle(at(0.0));
        angles_.push_back(0.0);
        for (int k = 1; k <= kRailSamples; ++k) {
            const double a = wrapNear(axis.angle(at(static_cast<double>(k) / kRailSamples)) - a0_, angles_.back());
            angles_.push_back(a);
        }
        sign_ = angles_.back() > 0.0 ? 1.0 : -1.0;
        if (std::abs(std::abs(angles_.back()) - 2 * kPi) > kFullTurnSlack)
            throw GeometryError(name + ": the rail does not go once around the axis through the rails' centres");
        for (int k = 1; k <= kRailSamples; ++k)
            if (sign_ * (angles_[k] - angles_[k - 1]) < -kMonotoneSlack)
                throw GeometryError(name + ": the rail is not star-shaped about the axis (a half-plane at the axis "
                                           "cuts it more than once)");
    }

    // Point of the rail at angle theta in [0, 2π] about the axis, measured from its start.
    Vec3 pointAt(double theta) const
    {
        const double target = sign_ > 0 ? theta : theta - 2 * kPi;
        // The bracket: the last sample whose signed angle is below the target (the signed angles
        // increase, checked in the constructor), by bisection.
        int k = 0, hiK = kRailSamples - 1;
        while (k < hiK) {
            const int mid = (k + hiK + 1) / 2;
            if (sign_ * (angles_[mid] - target) < 0.0) k = mid;
            else hiK = mid - 1;
        }
        double lo = static_cast<double>(k) / kRailSamples;
        double hi = static_cast<double>(k + 1) / kRailSamples;
        const double ref = angles_[k];
        // Regula falsi with the Illinois modification (Dowell & Jarratt 1971) on the monotone
        // angle: superlinear, and never leaves the bracket.
        double flo = sign_ * (angles_[k] - target);
        double fhi = sign_ * (angles_[k + 1] - target);
        double x = lo;
        int side = 0;
        for (int it = 0; it < kRootSteps && hi - lo > kParameterResolution; ++it) {
            x = fhi != flo ? (lo * fhi - hi * flo) / (fhi - flo) : 0.5 * (lo + hi);
            if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
            const double fx = sign_ * (wrapNear(axis_.angle(at(x)) - a0_, ref) - target);
            if (fx == 0.0) break;
            if (fx < 0.0) {
                lo = x;
                flo = fx;
                if (side == -1) fhi *= 0.5;
                side = -1;
            } else {
                hi = x;
                fhi = fx;
                if (side == 1) flo *= 0.5;
                side = 1;
            }
        }
        return at(x);
    }

private:
    Vec3 at(double s) const
    {
        double t = v0_ + s;
        if (t > 1.0) t -= 1.0;
        return curve_.evaluate(t);
    }

    Curve3d curve_;
    AxisFrame axis_;
    std::string name_;
    double v0_ = 0.0;
    double a0_ = 0.0;
    double sign_ = 1.0;
    std::vector<double> angles_;
};

// M_θ of eq. 5-9 (see the header for the reading).
Eigen::Affine3d sectionTransform(const AxisFrame& axis, double theta, const Vec3& p0, const Vec3& q0, const Vec3& p,
                                 const Vec3& q)
{
    const Eigen::Matrix3d rot = Eigen::AngleAxisd(theta, axis.dir).toRotationMatrix();
    const Vec3 chord = rot * (q0 - p0);
    const Eigen::Matrix3d align = Eigen::Quaterniond::FromTwoVectors(chord, q - p).toRotationMatrix();
    const double scale = (q - p).norm() / (q0 - p0).norm();
    Eigen::Affine3d m = Eigen::Affine3d::Identity();
    m.linear() = scale * align * rot;
    m.translation() = p - m.linear() * p0;
    return m;
}

}  // namespace

ApproximatedSurface railRotation(const Curve3d& rail1, const Curve3d& rail2, const Curve3d& input,
                                 const ApproximationOptions& options)
{
    Curve3d profile = normalizedCurve(input);
    const double size = std::max({rail1.controlSize(), rail2.controlSize(), profile.controlSize()});
    const double meet = kMeetRelative * size;
    const double tolerance = approximationTolerance(options.tolerance, kDefaultApproximationRelative * size,
                                                    coordinateScale({&rail1, &rail2, &profile}));

    AxisFrame axis;
    const Vec3 o1 = boxCentre(normalizedCurve(rail1));
    const Vec3 o2 = boxCentre(normalizedCurve(rail2));
    axis.origin = o1;
    axis.dir = (o2 - o1).norm() > 1e-9 * size ? Vec3((o2 - o1).normalized()) : bestFitPlaneNormal({rail1});
    axis.e1 = axis.dir.unitOrthogonal();
    axis.e2 = axis.dir.cross(axis.e1);

    // The profile may be drawn from either rail.
    const auto distanceTo = [](const Curve3d& c, const Vec3& x) { return projectToCurve(normalizedCurve(c), x).distance; };
    if (distanceTo(rail1, profile.evaluate(0.0)) + distanceTo(rail2, profile.evaluate(1.0)) >
        distanceTo(rail1, profile.evaluate(1.0)) + distanceTo(rail2, profile.evaluate(0.0)))
        profile = reversedCurve(profile);
    const Vec3 p0 = profile.evaluate(0.0);
    const Vec3 q0 = profile.evaluate(1.0);
    if (!((q0 - p0).norm() > meet)) throw GeometryError("curves[2]: the profile's ends coincide; it connects nothing");
    const Rail r1(rail1, p0, axis, meet, "curves[0]");
    const Rail r2(rail2, q0, axis, meet, "curves[1]");

    const int n = profile.pointCount();
    const int h = profile.isRational() ? 4 : 3;
    std::vector<double> us;
    for (int i = 0; i <= 2 * n; ++i) us.push_back(static_cast<double>(i) / (2 * n));
    // Profile samples and their u bases, fixed for every probe (The NURBS Book A2.1, A2.2).
    const int pu = profile.degree();
    std::vector<Vec3> profilePts;
    std::vector<int> uSpan;
    std::vector<std::vector<double>> uBasis;
    for (double u : us) {
        profilePts.push_back(profile.evaluate(u));
        uSpan.push_back(findSpan(pu, profile.knots(), u));
        uBasis.emplace_back(pu + 1);
        basisFunctions(uSpan.back(), u, pu, profile.knots(), uBasis.back().data());
    }
    const auto section = [&](double theta) {
        if (theta == 0.0 || theta == 2 * kPi) return Eigen::Affine3d(Eigen::Affine3d::Identity());
        return sectionTransform(axis, theta, p0, q0, r1.pointAt(theta), r2.pointAt(theta));
    };

    int count = kInitialSections;  // distinct sections, at θ_k = 2πk / count
    for (;;) {
        ControlMatrix data(count, static_cast<Eigen::Index>(n) * h);
        for (int k = 0; k < count; ++k) {
            const Eigen::Affine3d m = section(2 * kPi * k / count);
            for (int i = 0; i < n; ++i) {
                const double w = profile.weight(i);
                data.block(k, static_cast<Eigen::Index>(i) * h, 1, 3) = w * (m * profile.points()[i]).transpose();
                if (h == 4) data(k, static_cast<Eigen::Index>(i) * h + 3) = w;
            }
        }
        const KnotVector knotsV = periodicUniformKnots(3, count);
        const ControlMatrix net = periodicCubicInterpolation(data);
        double deviation = 0.0;
        Eigen::RowVectorXd iso(net.cols());
        for (int k = 0; k < count; ++k)
            for (int q = 1; q < kProbesPerInterval; ++q) {
                const double vm = (k + static_cast<double>(q) / kProbesPerInterval) / count;
                const Eigen::Affine3d m = section(2 * kPi * vm);
                // The probe's iso-curve rows (v basis applied to the net), then the fixed u bases.
                const int vSpan = findSpan(3, knotsV, vm);
                double nv[4];
                basisFunctions(vSpan, vm, 3, knotsV, nv);
                iso.noalias() = nv[0] * net.row(vSpan - 3) + nv[1] * net.row(vSpan - 2) + nv[2] * net.row(vSpan - 1) +
                                nv[3] * net.row(vSpan);
                for (size_t i = 0; i < us.size(); ++i) {
                    Eigen::Vector4d hp = Eigen::Vector4d::Zero();
                    for (int c = 0; c <= pu; ++c) {
                        const Eigen::Index col = static_cast<Eigen::Index>(uSpan[i] - pu + c) * h;
                        hp.head<3>() += uBasis[i][c] * iso.segment(col, 3).transpose();
                        hp(3) += uBasis[i][c] * (h == 4 ? iso(col + 3) : 1.0);
                    }
                    deviation = std::max(deviation, (hp.head<3>() / hp(3) - m * profilePts[i]).norm());
                }
            }
        // Periodic cubic interpolation errs as h^4 (de Boor ch. IV): r times over tolerance needs
        // r^(1/4) times the sections, with a margin for the probes' estimate.
        const int next = deviation <= tolerance
                             ? count
                             : std::min(options.maxPoints - 3,
                                        std::max(count + 1, static_cast<int>(std::ceil(
                                                                count * std::pow(kGrowthMargin * deviation / tolerance, 0.25)))));
        if (next <= count)
            return ApproximatedSurface{Surface3d::fromGroupedRows(Direction::V, pu, 3, profile.knots(), knotsV, net,
                                                                  profile.isRational()),
                                       deviation, tolerance};
        count = next;
    }
}

ControlMatrix periodicCubicInterpolation(const ControlMatrix& data)
{
    // Uniform cubic B-spline at its knots: S(t_{k+3}) = (P_k + 4 P_{k+1} + P_{k+2}) / 6, indices
    // mod K. With Q_k = P_{k+1} it is the cyclic tridiagonal system (Q_{k-1} + 4 Q_k + Q_{k+1}) / 6
    // = D_k (strictly diagonally dominant, so well conditioned), solved in O(K) by the Thomas
    // algorithm with the Sherman-Morrison correction for the two corner entries (Press et al.,
    // "Numerical Recipes", §2.7, cyclic tridiagonal systems).
    const int K = static_cast<int>(data.rows());
    if (K < 3) throw GeometryError("periodic interpolation needs at least 3 rows");
    const double a = 1.0 / 6.0, b = 4.0 / 6.0, c = 1.0 / 6.0;
    const double alpha = c, beta = a;  // A(K-1, 0) and A(0, K-1)
    const double gamma = -b;
    std::vector<double> diag(K, b);
    diag[0] = b - gamma;
    diag[K - 1] = b - alpha * beta / gamma;
    // Forward elimination of tridiag(a, diag, c), shared by both right-hand sides.
    std::vector<double> cp(K), m(K);
    m[0] = diag[0];
    cp[0] = c / m[0];
    for (int i = 1; i < K; ++i) {
        m[i] = diag[i] - a * cp[i - 1];
        cp[i] = c / m[i];
    }
    const auto solve = [&](Eigen::MatrixXd& x) {
        x.row(0) /= m[0];
        for (int i = 1; i < K; ++i) x.row(i) = (x.row(i) - a * x.row(i - 1)) / m[i];
        for (int i = K - 2; i >= 0; --i) x.row(i) -= cp[i] * x.row(i + 1);
    };
    Eigen::MatrixXd x = data;
    solve(x);
    Eigen::MatrixXd z = Eigen::MatrixXd::Zero(K, 1);
    z(0, 0) = gamma;
    z(K - 1, 0) = alpha;
    solve(z);
    const double fact = 1.0 / (1.0 + z(0, 0) + beta * z(K - 1, 0) / gamma);
    const Eigen::RowVectorXd correction = fact * (x.row(0) + (beta / gamma) * x.row(K - 1));
    x -= z.col(0) * correction;
    // P_j = Q_{j-1}.
    ControlMatrix out(K + 3, data.cols());
    out.row(0) = x.row(K - 1);
    out.middleRows(1, K - 1) = x.topRows(K - 1);
    out.bottomRows(3) = out.topRows(3);  // the wrapped points of a closed curve
    return out;
}

}  // namespace sculptline::solvers::surfaces
