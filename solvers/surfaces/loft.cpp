#include "solvers/surfaces/loft.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/bspline/projection.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <string>

namespace sculptline::solvers::surfaces {

namespace {

void requireSections(const std::vector<Curve3d>& sections)
{
    if (sections.size() < 2)
        throw GeometryError("curves: a loft needs at least two sections, got " + std::to_string(sections.size()));
}

// Ends closer than this fraction of the curve's size make a closed loop (round-off of a stroke
// that was snapped shut, or of opening a periodic curve).
constexpr double kClosedRelative = 1e-9;
// Samples for the vector area of a closed section.
constexpr int kAreaSamples = 64;

bool isLoop(const Curve3d& c)
{
    return c.isClosed() ||
           (c.evaluate(c.domainStart()) - c.evaluate(c.domainEnd())).norm() <= kClosedRelative * c.controlSize();
}

// The vector area (1/2) sum x_i x x_(i+1) of a closed polygon through samples of the loop: its
// direction is the loop's winding normal (right-hand rule).
Eigen::Vector3d vectorArea(const Curve3d& c)
{
    Eigen::Vector3d area = Eigen::Vector3d::Zero();
    Eigen::Vector3d prev = c.evaluate(c.domainStart());
    for (int k = 1; k <= kAreaSamples; ++k) {
        const Eigen::Vector3d x = c.evaluate(c.domainStart() + (c.domainEnd() - c.domainStart()) * k / kAreaSamples);
        area += 0.5 * prev.cross(x);
        prev = x;
    }
    return area;
}

}  // namespace

Surface3d loft(const std::vector<Curve3d>& sections, const LoftOptions& options)
{
    return LoftBuilder(sections, options).surface();
}

LoftBuilder::LoftBuilder(const std::vector<Curve3d>& sections, const LoftOptions& options) : options_(options)
{
    reset(sections);
}

const Surface3d& LoftBuilder::reset(const std::vector<Curve3d>& sections)
{
    requireSections(sections);
    if (options_.crossDegree < 1) throw GeometryError("crossDegree: must be >= 1");
    // Sections sketched in opposite directions would twist the surface: each is turned to run like
    // its predecessor (open sections: its ends nearer the predecessor's same ends; closed ones
    // after a closed predecessor: the same winding). A closed periodic section after a closed
    // predecessor is opened at its point nearest the predecessor's seam, so the seams line up.
    std::vector<Curve3d> oriented;
    reversed_.assign(sections.size(), false);
    seams_.assign(sections.size(), std::nullopt);
    for (size_t k = 0; k < sections.size(); ++k) {
        Curve3d c = normalizedCurve(sections[k]);
        if (k > 0) {
            const Curve3d& prev = oriented.back();
            if (isLoop(sections[k]) && isLoop(prev)) {
                if (sections[k].isClosed()) {
                    seams_[k] = projectToCurve(sections[k], prev.evaluate(0.0)).u;
                    c = normalizedCurve(sections[k].openAt(*seams_[k]));
                }
                reversed_[k] = vectorArea(c).dot(vectorArea(prev)) < 0.0;
            } else {
                const Eigen::Vector3d p0 = prev.evaluate(0.0), p1 = prev.evaluate(1.0);
                const Eigen::Vector3d c0 = c.evaluate(0.0), c1 = c.evaluate(1.0);
                reversed_[k] = (p0 - c1).norm() + (p1 - c0).norm() < (p0 - c0).norm() + (p1 - c1).norm();
            }
            if (reversed_[k]) c = reversedCurve(c);
        }
        oriented.push_back(std::move(c));
    }
    const std::vector<Curve3d> compatible = makeCompatible(oriented);
    layout_ = CurveLayout{compatible.front().degree(), compatible.front().knots()};
    rational_ = compatible.front().isRational();
    columns_ = rational_ ? 4 : 3;
    const int n = layout_.pointCount();
    data_.resize(static_cast<Eigen::Index>(sections.size()), static_cast<Eigen::Index>(n) * columns_);
    for (size_t k = 0; k < compatible.size(); ++k) {
        const ControlMatrix rows = compatible[k].homogeneous();
        for (int i = 0; i < n; ++i) data_.block(k, i * columns_, 1, columns_) = rows.row(i);
    }
    // Chords between Euclidean control points (eq. 10.8); homogeneous rows are divided by w first.
    ControlMatrix euclid(data_.rows(), static_cast<Eigen::Index>(n) * 3);
    for (Eigen::Index k = 0; k < data_.rows(); ++k)
        for (int i = 0; i < n; ++i) {
            const double w = rational_ ? data_(k, i * columns_ + 3) : 1.0;
            euclid.block(k, i * 3, 1, 3) = data_.block(k, i * columns_, 1, 3) / w;
        }
    const int q = std::min(options_.crossDegree, static_cast<int>(sections.size()) - 1);
    try {
        interpolator_ = std::make_unique<CurveInterpolator>(chordParameters(euclid, 3), q);
    } catch (const GeometryError&) {
        throw GeometryError("curves: two consecutive sections coincide; a loft needs distinct sections");
    }
    solve();
    return *surface_;
}

bool LoftBuilder::setSection(int index, const Curve3d& section)
{
    const std::optional<Curve3d> c = conformToLayout(laidOut(index, section), layout_);
    if (!c || c->isRational() != rational_) return false;
    const ControlMatrix rows = c->homogeneous();
    for (int i = 0; i < layout_.pointCount(); ++i) data_.block(index, i * columns_, 1, columns_) = rows.row(i);
    return true;
}

Curve3d LoftBuilder::laidOut(int index, const Curve3d& section) const
{
    const Curve3d c = seams_[index] && section.isClosed() ? normalizedCurve(section.openAt(*seams_[index]))
                                                          : normalizedCurve(section);
    return reversed_[index] ? reversedCurve(c) : c;
}

const Surface3d& LoftBuilder::update(int index, const Curve3d& section)
{
    if (index < 0 || index >= data_.rows()) throw GeometryError("index: no section " + std::to_string(index));
    if (!setSection(index, section)) {
        // A section with new knots: rebuild everything from the stored sections.
        std::vector<Curve3d> all;
        for (Eigen::Index k = 0; k < data_.rows(); ++k) {
            ControlMatrix rows(layout_.pointCount(), columns_);
            for (int i = 0; i < layout_.pointCount(); ++i) rows.row(i) = data_.block(k, i * columns_, 1, columns_);
            all.push_back(k == index ? laidOut(index, section)
                                     : Curve3d::fromHomogeneous(layout_.degree, layout_.knots, rows, rational_));
        }
        return reset(all);
    }
    solve();
    return *surface_;
}

const Surface3d& LoftBuilder::update(const std::vector<Curve3d>& sections)
{
    if (static_cast<Eigen::Index>(sections.size()) != data_.rows()) return reset(sections);
    for (size_t k = 0; k < sections.size(); ++k)
        if (!setSection(static_cast<int>(k), sections[k])) return reset(sections);
    solve();
    return *surface_;
}

void LoftBuilder::solve()
{
    const ControlMatrix net = interpolator_->solve(data_);  // row j: control row j across the sections
    if (rational_) {
        for (Eigen::Index j = 0; j < net.rows(); ++j)
            for (int i = 0; i < layout_.pointCount(); ++i)
                if (!(net(j, i * columns_ + 3) > 0.0))
                    throw GeometryError("curves: the sections' weights differ too much; interpolated weights "
                                        "are not positive");
    }
    surface_ = std::make_unique<Surface3d>(Surface3d::fromGroupedRows(Direction::V, layout_.degree,
                                                                      interpolator_->degree(), layout_.knots,
                                                                      interpolator_->knots(), net, rational_));
}

Surface3d transposed(const Surface3d& s)
{
    std::vector<Eigen::Vector3d> pts;
    std::vector<double> w;
    for (int j = 0; j < s.countV(); ++j)
        for (int i = 0; i < s.countU(); ++i) {
            pts.push_back(s.point(i, j));
            if (s.isRational()) w.push_back(s.weight(i, j));
        }
    return Surface3d(s.degreeV(), s.degreeU(), s.knotsV(), s.knotsU(), s.countV(), s.countU(), pts, w);
}

}  // namespace sculptline::solvers::surfaces
